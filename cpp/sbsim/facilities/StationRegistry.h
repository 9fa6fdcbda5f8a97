#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/facilities/DenmPhase.h"
#include "sbsim/facilities/StationFacilities.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/StationIds.h"

namespace sbsim::facilities {

/// The run's stations, each with its facilities (LDM, DENM memory): the services write them as
/// messages arrive, the storyboard's V2X conditions read them. A station is known by its id and by
/// its index (radio::StationIds: interned once, valid for the run), which the per-message paths use
/// so that a reception costs no string lookup. Reads (find) may run on several threads at once
/// while nobody writes; the services write only between storyboard passes.
class SBSIM_API StationRegistry {
public:
    using Index = radio::StationIds::Index;

    /// The index of `station` for the run (made on first use; its facilities are not).
    Index intern(std::string_view station) { return ids_.intern(station); }
    const std::string& name(Index station) const { return ids_.name(station); }

    /// The facilities of `station`, made empty on first use.
    StationFacilities& of(Index station);
    StationFacilities& of(std::string_view station) { return of(intern(station)); }
    /// The facilities of `station`, or null if it has none (yet, or any more).
    const StationFacilities* find(std::string_view station) const;
    const StationFacilities* find(Index station) const {
        return station < byIndex_.size() ? byIndex_[station].get() : nullptr;
    }
    /// `station` left the run: its facilities go (its index stays its own).
    void remove(std::string_view station);
    std::size_t size() const { return size_; }

    /// Drops what expired at `station` before `now`, reporting each expired DENM event.
    void dropExpired(Index station, kernel::SimTime now);
    void dropExpired(std::string_view station, kernel::SimTime now);

    /// Where DENM phase events go (not owned; null: nowhere).
    void setPhaseSink(DenmPhaseSink* sink) { sink_ = sink; }
    void report(const DenmPhaseEvent& event) const;

    /// Unique per registry in the process: tells a cached index's table apart from another
    /// registry made at the same address.
    std::uint64_t identity() const { return identity_; }

private:
    radio::StationIds ids_;
    std::vector<std::unique_ptr<StationFacilities>> byIndex_;  // null: none (yet, or any more)
    std::size_t size_ = 0;
    DenmPhaseSink* sink_ = nullptr;
    std::uint64_t identity_ = nextIdentity();

    static std::uint64_t nextIdentity();
};

}  // namespace sbsim::facilities
