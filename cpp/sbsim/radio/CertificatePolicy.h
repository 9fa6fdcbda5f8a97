#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <unordered_map>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/FrameSize.h"

namespace sbsim::radio {

/// When a station's signed messages carry its full certificate, as Vanetza's v3
/// DefaultSignHeaderPolicy decides (TS 103 097 v2.1.1 §7.1.1): a CAM carries it if none did in the
/// last 950 ms (one second less Vanetza's 50 ms tolerance, so a 1 Hz CAM always carries it) or if
/// the station has heard a station it did not know since its last CAM (Vanetza's verify service
/// calls request_certificate() on a CAM from an unknown station); otherwise the certificate's
/// digest. DENMs and other messages always carry the certificate.
///
/// Memory: a station remembers the stations it heard for kForgetAfter (20 s, GeoNetworking's
/// location table entry lifetime itsGnLifetimeLocTE); one heard again after that counts as new.
/// Stations silent that long are dropped entirely (their state then equals a fresh one's).
class SBSIM_API CertificatePolicy {
public:
    static constexpr kernel::SimTime kCertificateInterval = kernel::SimTime::fromMilliseconds(950);
    static constexpr kernel::SimTime kForgetAfter = kernel::SimTime::fromMilliseconds(20'000);

    /// `secured` false: every message goes unsecured (the radio file's `security = "none"`).
    explicit CertificatePolicy(bool secured = true) : secured_(secured) {}
    void setSecured(bool secured) { secured_ = secured; }
    bool secured() const { return secured_; }

    /// How `station`'s message of `profile`, signed `now`, names its signer; records a certificate.
    SignerIdentifier sign(std::string_view station, SecurityProfile profile, kernel::SimTime now);
    /// `station` received a message of `sender` at `now`.
    void heard(std::string_view station, std::string_view sender, SecurityProfile profile, kernel::SimTime now);

    /// Stations with state, for tests of the memory bound.
    std::size_t stations() const { return stations_.size(); }

private:
    struct Station {
        std::optional<kernel::SimTime> nextCertificate;  // none: the next CAM carries it
        bool requested = false;                          // a new station was heard
        kernel::SimTime lastActive;
        std::unordered_map<std::uint64_t, kernel::SimTime> known;  // sender's key -> last heard
    };
    Station& of(std::string_view station, kernel::SimTime now);
    void forgetOld(kernel::SimTime now);

    bool secured_;
    // By CounterRandom::keyOf(id): asked once per reception, where building a string key cost more
    // than the reception.
    std::unordered_map<std::uint64_t, Station> stations_;
    kernel::SimTime lastSweep_;
};

}  // namespace sbsim::radio
