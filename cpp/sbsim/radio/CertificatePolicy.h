#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/FrameSize.h"
#include "sbsim/radio/LastHeard.h"
#include "sbsim/radio/StationIds.h"

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
/// What was heard is kept by sender — per sender, when each station last heard it (LastHeard) — so
/// the receptions of one frame touch one small table instead of one per receiver (on a full city a
/// cache miss per reception, two thirds of the disc model's run). A station that signed nothing
/// for that long is dropped (its next CAM carries the certificate either way).
///
/// Stations are known by index (index(): interned once for the run), so a reception, which the
/// medium reports with the indices it already has, costs no string hashing.
class SBSIM_API CertificatePolicy {
public:
    static constexpr kernel::SimTime kCertificateInterval = kernel::SimTime::fromMilliseconds(950);
    static constexpr kernel::SimTime kForgetAfter = kernel::SimTime::fromMilliseconds(20'000);
    using Index = StationIds::Index;

    /// `secured` false: every message goes unsecured (the radio file's `security = "none"`).
    explicit CertificatePolicy(bool secured = true) : secured_(secured) {}
    void setSecured(bool secured) { secured_ = secured; }
    bool secured() const { return secured_; }

    /// The index of `station` here, for the run.
    Index index(std::string_view station) { return ids_.intern(station); }
    const std::string& name(Index station) const { return ids_.name(station); }
    /// The index of `station`, if it was interned.
    std::optional<Index> find(std::string_view station) const { return ids_.find(station); }

    /// How `station`'s message of `profile`, signed `now`, names its signer; records a certificate.
    SignerIdentifier sign(Index station, SecurityProfile profile, kernel::SimTime now);
    SignerIdentifier sign(std::string_view station, SecurityProfile profile, kernel::SimTime now) {
        return secured_ ? sign(index(station), profile, now) : SignerIdentifier::None;
    }
    /// `station` received a message of `sender` at `now`.
    void heard(Index station, Index sender, SecurityProfile profile, kernel::SimTime now);
    /// Each of `stations` (distinct; fastest in ascending order) received one message of `sender`
    /// at `now`: as heard() for each, with one walk through the sender's table.
    void heardAll(std::span<const Index> stations, Index sender, SecurityProfile profile, kernel::SimTime now);
    /// The same for a list that may come again unchanged for the sender's next frames (a medium's
    /// receivers of the step; it must not change while held): a repeat costs no walk (LastHeard::hearList).
    void heardAll(LastHeard::List stations, Index sender, SecurityProfile profile, kernel::SimTime now);
    /// Whether a medium's `next` list of `sender`'s receivers equals its `last` (the medium shares
    /// the last again then): compared as the sender's table will split them (LastHeard::compare).
    bool sameList(Index sender, std::span<const Index> last, std::span<const Index> next);
    /// The lists sameList() last compared for `sender`, shared as `from` and `to`: the frames of
    /// `to` take that comparison's split (LastHeard::expect).
    void expectList(Index sender, LastHeard::List from, LastHeard::List to);
    void heard(std::string_view station, std::string_view sender, SecurityProfile profile, kernel::SimTime now) {
        if (secured_) heard(index(station), index(sender), profile, now);
    }

    /// Stations with state, for tests of the memory bound.
    std::size_t stations() const { return active_; }
    /// Receptions remembered (one per station and sender heard), for tests of the memory bound.
    std::size_t remembered() const;

private:
    struct Station {
        bool active = false;                             // has state (else as a fresh station)
        std::optional<kernel::SimTime> nextCertificate;  // none: the next CAM carries it
        bool requested = false;                          // a new station was heard
        kernel::SimTime lastActive;
    };
    Station& of(Index station, kernel::SimTime now);
    /// of() once forgetOld(now) ran: a frame's unknown receivers (a whole list at a table's first
    /// fill) pay the sweep's check once, not once each.
    Station& activate(Index station, kernel::SimTime now);
    void forgetOld(kernel::SimTime now);
    /// heardAll's common part: `hear(table, since)` records a frame's stations in the sender's
    /// table and leaves the ones it did not know in unknown_.
    template <typename Hear>
    void heardBy(Index sender, SecurityProfile profile, kernel::SimTime now, Hear&& hear);

    bool secured_;
    StationIds ids_;
    std::vector<Station> stations_;   // by index
    std::vector<LastHeard> heardBy_;  // by sender's index: who heard it, when
    std::vector<Index> unknown_;      // scratch of heardAll
    std::size_t active_ = 0;
    kernel::SimTime lastSweep_;
};

}  // namespace sbsim::radio
