#include "sbsim/radio/CertificatePolicy.h"

#include <algorithm>

namespace sbsim::radio {

CertificatePolicy::Station& CertificatePolicy::of(Index station, kernel::SimTime now) {
    forgetOld(now);
    return activate(station, now);
}

CertificatePolicy::Station& CertificatePolicy::activate(Index station, kernel::SimTime now) {
    if (station >= stations_.size()) stations_.resize(station + 1);
    Station& s = stations_[station];
    if (!s.active) {
        s.active = true;
        ++active_;
    }
    s.lastActive = now;
    return s;
}

void CertificatePolicy::forgetOld(kernel::SimTime now) {
    // A sweep every kForgetAfter keeps each entry at most twice that long.
    if (now - lastSweep_ < kForgetAfter) return;
    lastSweep_ = now;
    for (Station& s : stations_) {
        if (s.active && now - s.lastActive > kForgetAfter) {
            s = Station{};  // its certificate is due anyway: as a fresh station
            --active_;
        }
    }
    for (LastHeard& heard : heardBy_) heard.forgetBefore(now - kForgetAfter);
}

std::size_t CertificatePolicy::remembered() const {
    std::size_t n = 0;
    for (const LastHeard& heard : heardBy_) n += heard.size();
    return n;
}

SignerIdentifier CertificatePolicy::sign(Index station, SecurityProfile profile, kernel::SimTime now) {
    if (!secured_) return SignerIdentifier::None;
    if (profile != SecurityProfile::Cam) return SignerIdentifier::Certificate;
    Station& s = of(station, now);
    if (s.nextCertificate && now < *s.nextCertificate && !s.requested) return SignerIdentifier::Digest;
    s.nextCertificate = now + kCertificateInterval;
    s.requested = false;
    return SignerIdentifier::Certificate;
}

void CertificatePolicy::heard(Index station, Index sender, SecurityProfile profile, kernel::SimTime now) {
    if (!secured_) return;
    forgetOld(now);
    if (sender >= heardBy_.size()) heardBy_.resize(sender + 1);
    const auto before = heardBy_[sender].hear(station, now);
    const bool wasKnown = before && now - *before <= kForgetAfter;
    // Vanetza asks for its own certificate only on a CAM from an unknown station.
    if (!wasKnown && profile == SecurityProfile::Cam) activate(station, now).requested = true;
}

template <typename Hear>
void CertificatePolicy::heardBy(Index sender, SecurityProfile profile, kernel::SimTime now, Hear&& hear) {
    forgetOld(now);
    if (sender >= heardBy_.size()) heardBy_.resize(sender + 1);
    unknown_.clear();
    hear(heardBy_[sender], now - kForgetAfter);
    if (profile != SecurityProfile::Cam) return;
    for (const Index station : unknown_) activate(station, now).requested = true;  // swept above
}

void CertificatePolicy::heardAll(std::span<const Index> stations, Index sender, SecurityProfile profile,
                                 kernel::SimTime now) {
    if (!secured_ || stations.empty()) return;
    heardBy(sender, profile, now,
            [&](LastHeard& table, kernel::SimTime since) { table.hearAll(stations, now, since, unknown_); });
}

void CertificatePolicy::heardAll(LastHeard::List stations, Index sender, SecurityProfile profile, kernel::SimTime now) {
    if (!secured_ || stations == nullptr || stations->empty()) return;
    heardBy(sender, profile, now, [&](LastHeard& table, kernel::SimTime since) {
        table.hearList(std::move(stations), now, since, unknown_);
    });
}

bool CertificatePolicy::sameList(Index sender, std::span<const Index> last, std::span<const Index> next) {
    if (!secured_) return std::ranges::equal(last, next);
    if (sender >= heardBy_.size()) heardBy_.resize(sender + 1);
    return heardBy_[sender].compare(last, next);
}

void CertificatePolicy::expectList(Index sender, LastHeard::List from, LastHeard::List to) {
    if (!secured_ || sender >= heardBy_.size()) return;
    heardBy_[sender].expect(std::move(from), std::move(to));
}

}  // namespace sbsim::radio
