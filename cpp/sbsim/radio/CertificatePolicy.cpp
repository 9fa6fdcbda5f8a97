#include "sbsim/radio/CertificatePolicy.h"

#include <iterator>

#include "sbsim/radio/CounterRandom.h"

namespace sbsim::radio {

CertificatePolicy::Station& CertificatePolicy::of(std::uint64_t station, kernel::SimTime now) {
    forgetOld(now);
    Station& s = stations_[station];
    s.lastActive = now;
    return s;
}

void CertificatePolicy::forgetOld(kernel::SimTime now) {
    // A sweep every kForgetAfter keeps each entry at most twice that long.
    if (now - lastSweep_ < kForgetAfter) return;
    lastSweep_ = now;
    std::erase_if(stations_, [&](const auto& entry) { return now - entry.second.lastActive > kForgetAfter; });
    for (auto it = heardBy_.begin(); it != heardBy_.end();) {
        it->second.forgetBefore(now - kForgetAfter);
        it = it->second.size() == 0 ? heardBy_.erase(it) : std::next(it);
    }
    lastHeardBy_ = nullptr;
}

std::size_t CertificatePolicy::remembered() const {
    std::size_t n = 0;
    for (const auto& [sender, heard] : heardBy_) n += heard.size();
    return n;
}

SignerIdentifier CertificatePolicy::sign(std::string_view station, SecurityProfile profile, kernel::SimTime now) {
    if (!secured_) return SignerIdentifier::None;
    if (profile != SecurityProfile::Cam) return SignerIdentifier::Certificate;
    Station& s = of(CounterRandom::keyOf(station), now);
    if (s.nextCertificate && now < *s.nextCertificate && !s.requested) return SignerIdentifier::Digest;
    s.nextCertificate = now + kCertificateInterval;
    s.requested = false;
    return SignerIdentifier::Certificate;
}

void CertificatePolicy::heard(std::string_view station, std::string_view sender, SecurityProfile profile,
                              kernel::SimTime now) {
    heard(CounterRandom::keyOf(station), CounterRandom::keyOf(sender), profile, now);
}

void CertificatePolicy::heard(std::uint64_t station, std::uint64_t sender, SecurityProfile profile,
                              kernel::SimTime now) {
    if (!secured_) return;
    forgetOld(now);
    if (lastHeardBy_ == nullptr || lastSender_ != sender) {
        lastHeardBy_ = &heardBy_[sender];
        lastSender_ = sender;
    }
    const auto before = lastHeardBy_->hear(station, now);
    const bool wasKnown = before && now - *before <= kForgetAfter;
    // Vanetza asks for its own certificate only on a CAM from an unknown station.
    if (!wasKnown && profile == SecurityProfile::Cam) of(station, now).requested = true;
}

}  // namespace sbsim::radio
