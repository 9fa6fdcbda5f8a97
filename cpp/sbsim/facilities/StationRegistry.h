#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "sbsim/facilities/DenmPhase.h"
#include "sbsim/facilities/StationFacilities.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::facilities {

/// The run's stations by id, each with its facilities (LDM, DENM memory): the services write them
/// as messages arrive, the storyboard's V2X conditions read them. Reads (find) may run on several
/// threads at once while nobody writes; the services write only between storyboard passes.
class SBSIM_API StationRegistry {
public:
    /// The facilities of `station`, made empty on first use.
    StationFacilities& of(const std::string& station);
    /// The facilities of `station`, or null if it has none (yet, or any more).
    const StationFacilities* find(std::string_view station) const;
    /// `station` left the run: its facilities go.
    void remove(std::string_view station);
    std::size_t size() const { return stations_.size(); }

    /// Drops what expired at `station` before `now`, reporting each expired DENM event.
    void dropExpired(const std::string& station, kernel::SimTime now);

    /// Where DENM phase events go (not owned; null: nowhere).
    void setPhaseSink(DenmPhaseSink* sink) { sink_ = sink; }
    void report(const DenmPhaseEvent& event) const;

private:
    std::map<std::string, std::unique_ptr<StationFacilities>, std::less<>> stations_;
    DenmPhaseSink* sink_ = nullptr;
};

}  // namespace sbsim::facilities
