#pragma once

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

/// What conditions may read during one evaluation pass (one SUMO step): the step's snapshot, the
/// time, and a spatial index over the snapshot built once for the step. Conditions never call
/// libsumo per vehicle.
class SBSIM_API EvaluationContext {
public:
    EvaluationContext(const traffic::VehicleSnapshot& snapshot, const traffic::NeighbourGrid& neighbours)
        : snapshot_(snapshot), neighbours_(neighbours) {}

    const traffic::VehicleSnapshot& snapshot() const { return snapshot_; }
    kernel::SimTime now() const { return snapshot_.time(); }
    /// Built over this snapshot with a cell size at least the largest radius any registered
    /// condition asked for (Condition::neighbourRadius()).
    const traffic::NeighbourGrid& neighbours() const { return neighbours_; }

private:
    const traffic::VehicleSnapshot& snapshot_;
    const traffic::NeighbourGrid& neighbours_;
};

}  // namespace sbsim::storyboard
