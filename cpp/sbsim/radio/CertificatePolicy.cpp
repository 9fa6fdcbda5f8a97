#include "sbsim/radio/CertificatePolicy.h"

#include "sbsim/radio/CounterRandom.h"

namespace sbsim::radio {

CertificatePolicy::Station& CertificatePolicy::of(std::string_view station, kernel::SimTime now) {
    forgetOld(now);
    Station& s = stations_[CounterRandom::keyOf(station)];
    s.lastActive = now;
    return s;
}

void CertificatePolicy::forgetOld(kernel::SimTime now) {
    // A sweep every kForgetAfter keeps each entry at most twice that long.
    if (now - lastSweep_ < kForgetAfter) return;
    lastSweep_ = now;
    for (auto it = stations_.begin(); it != stations_.end();) {
        Station& s = it->second;
        if (now - s.lastActive > kForgetAfter) {
            it = stations_.erase(it);  // its certificate is due anyway: as a fresh station
            continue;
        }
        std::erase_if(s.known, [&](const auto& entry) { return now - entry.second > kForgetAfter; });
        ++it;
    }
}

SignerIdentifier CertificatePolicy::sign(std::string_view station, SecurityProfile profile, kernel::SimTime now) {
    if (!secured_) return SignerIdentifier::None;
    if (profile != SecurityProfile::Cam) return SignerIdentifier::Certificate;
    Station& s = of(station, now);
    if (s.nextCertificate && now < *s.nextCertificate && !s.requested) return SignerIdentifier::Digest;
    s.nextCertificate = now + kCertificateInterval;
    s.requested = false;
    return SignerIdentifier::Certificate;
}

void CertificatePolicy::heard(std::string_view station, std::string_view sender, SecurityProfile profile,
                              kernel::SimTime now) {
    if (!secured_) return;
    Station& s = of(station, now);
    const auto [it, inserted] = s.known.try_emplace(CounterRandom::keyOf(sender), now);
    const bool wasKnown = !inserted && now - it->second <= kForgetAfter;
    it->second = now;
    // Vanetza asks for its own certificate only on a CAM from an unknown station.
    if (!wasKnown && profile == SecurityProfile::Cam) s.requested = true;
}

}  // namespace sbsim::radio
