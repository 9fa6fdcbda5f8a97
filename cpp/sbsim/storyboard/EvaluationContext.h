#pragma once

#include <stdexcept>
#include <string_view>

#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/ParallelFor.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/StepNeighbours.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/TrafficQueries.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

/// What conditions may read during one evaluation pass (one SUMO step): the step's snapshot, the
/// time, and a spatial index over the snapshot built once for the step. Conditions never call
/// libsumo directly; the few that need a value the snapshot lacks ask queries(), only for the
/// vehicles that reach them.
class SBSIM_API EvaluationContext {
public:
    EvaluationContext(const traffic::VehicleSnapshot& snapshot, const traffic::NeighbourGrid& neighbours,
                      traffic::TrafficQueries* queries = nullptr, kernel::ParallelFor* parallel = nullptr,
                      const facilities::StationRegistry* stations = nullptr,
                      const traffic::Penetration* penetration = nullptr)
        : EvaluationContext(snapshot, &neighbours, nullptr, queries, parallel, stations, penetration) {}
    /// The same with the step's grid built only if a condition asks for it (the storyboard's pass).
    EvaluationContext(const traffic::VehicleSnapshot& snapshot, const StepNeighbours& lazyNeighbours,
                      traffic::TrafficQueries* queries = nullptr, kernel::ParallelFor* parallel = nullptr,
                      const facilities::StationRegistry* stations = nullptr,
                      const traffic::Penetration* penetration = nullptr)
        : EvaluationContext(snapshot, nullptr, &lazyNeighbours, queries, parallel, stations, penetration) {}

    const traffic::VehicleSnapshot& snapshot() const { return snapshot_; }
    kernel::SimTime now() const { return snapshot_.time(); }
    /// Built over this snapshot with a cell size at least the largest radius any registered
    /// condition asked for (Condition::neighbourRadius()).
    /// Thread-safe; with a StepNeighbours, the first call of the step builds the grid.
    const traffic::NeighbourGrid& neighbours() const {
        return lazyNeighbours_ != nullptr ? lazyNeighbours_->get() : *neighbours_;
    }
    /// Throws std::logic_error if this context has none (a snapshot evaluated without SUMO).
    traffic::TrafficQueries& queries() const {
        if (queries_ == nullptr) throw std::logic_error("this evaluation has no traffic to query");
        return *queries_;
    }

    /// The process's worker pool, for work a condition does once per step in prepare(); null when
    /// evaluated without a simulation (then that work runs on the calling thread). Never used
    /// from test(), which already runs on the pool.
    kernel::ParallelFor* parallel() const { return parallel_; }
    /// What each station heard over V2X (its LDM, its DENM memory), which the V2X conditions read;
    /// null in a run without services (then nobody heard anything).
    const facilities::StationRegistry* stations() const { return stations_; }
    /// Whether the vehicle carries V2X equipment (the run's --penetration draw; everyone when the
    /// context has no penetration). Thread-safe: a hash of the id and the seed.
    bool equipped(std::string_view vehicleId) const {
        return penetration_ == nullptr || penetration_->equipped(vehicleId);
    }

private:
    /// Both public constructors' one initialisation: exactly one of the two grids is given.
    EvaluationContext(const traffic::VehicleSnapshot& snapshot, const traffic::NeighbourGrid* neighbours,
                      const StepNeighbours* lazyNeighbours, traffic::TrafficQueries* queries,
                      kernel::ParallelFor* parallel, const facilities::StationRegistry* stations,
                      const traffic::Penetration* penetration)
        : snapshot_(snapshot),
          neighbours_(neighbours),
          lazyNeighbours_(lazyNeighbours),
          queries_(queries),
          parallel_(parallel),
          stations_(stations),
          penetration_(penetration) {}

    const traffic::VehicleSnapshot& snapshot_;
    const traffic::NeighbourGrid* neighbours_;  // given built, or
    const StepNeighbours* lazyNeighbours_;      // built on first use
    traffic::TrafficQueries* queries_;
    kernel::ParallelFor* parallel_;
    const facilities::StationRegistry* stations_;
    const traffic::Penetration* penetration_;
};

}  // namespace sbsim::storyboard
