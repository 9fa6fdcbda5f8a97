#include "sbsim/radio/CertificatePolicy.h"

#include <algorithm>

namespace sbsim::radio {

std::size_t CertificatePolicy::KnownSenders::home(Index sender) const {
    // Fibonacci hashing: consecutive indices spread over the table.
    return static_cast<std::size_t>((static_cast<std::uint64_t>(sender) * 0x9E3779B97F4A7C15ULL) >> 32) &
           (slots_.size() - 1);
}

void CertificatePolicy::KnownSenders::rehash(std::size_t capacity) {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(capacity, Slot{});
    for (const Slot& s : old) {
        if (s.key == 0) continue;
        std::size_t k = home(s.key - 1);
        while (slots_[k].key != 0) k = (k + 1) & (capacity - 1);
        slots_[k] = s;
    }
}

std::pair<kernel::SimTime*, bool> CertificatePolicy::KnownSenders::tryEmplace(Index sender, kernel::SimTime now) {
    if (2 * (size_ + 1) > slots_.size()) rehash(std::max<std::size_t>(16, 2 * slots_.size()));
    const std::uint32_t key = sender + 1;
    std::size_t k = home(sender);
    while (slots_[k].key != 0) {
        if (slots_[k].key == key) return {&slots_[k].heard, false};
        k = (k + 1) & (slots_.size() - 1);
    }
    slots_[k] = {key, now};
    ++size_;
    return {&slots_[k].heard, true};
}

void CertificatePolicy::KnownSenders::keepSince(kernel::SimTime since) {
    size_ = 0;
    for (Slot& s : slots_) {
        if (s.key == 0) continue;
        if (s.heard < since) {
            s.key = 0;
        } else {
            ++size_;
        }
    }
    // Re-placed so that no kept sender sits behind a freed slot of its probe run.
    std::size_t capacity = 16;
    while (2 * size_ > capacity) capacity *= 2;
    rehash(size_ == 0 ? 0 : capacity);
}

CertificatePolicy::Station& CertificatePolicy::of(Index station, kernel::SimTime now) {
    forgetOld(now);
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
        if (!s.active) continue;
        if (now - s.lastActive > kForgetAfter) {
            s = Station{};  // its certificate is due anyway: as a fresh station
            --active_;
            continue;
        }
        s.known.keepSince(now - kForgetAfter);
    }
}

SignerIdentifier CertificatePolicy::sign(std::string_view station, SecurityProfile profile, kernel::SimTime now) {
    if (!secured_) return SignerIdentifier::None;
    if (profile != SecurityProfile::Cam) return SignerIdentifier::Certificate;
    Station& s = of(index(station), now);
    if (s.nextCertificate && now < *s.nextCertificate && !s.requested) return SignerIdentifier::Digest;
    s.nextCertificate = now + kCertificateInterval;
    s.requested = false;
    return SignerIdentifier::Certificate;
}

void CertificatePolicy::heard(Index station, Index sender, SecurityProfile profile, kernel::SimTime now) {
    if (!secured_) return;
    Station& s = of(station, now);
    const auto [last, inserted] = s.known.tryEmplace(sender, now);
    const bool wasKnown = !inserted && now - *last <= kForgetAfter;
    *last = now;
    // Vanetza asks for its own certificate only on a CAM from an unknown station.
    if (!wasKnown && profile == SecurityProfile::Cam) s.requested = true;
}

}  // namespace sbsim::radio
