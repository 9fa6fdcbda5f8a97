#pragma once

#include <pybind11/pybind11.h>

#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

/// One vehicle of the current snapshot, as custom conditions' test(vehicle) receives it.
/// Valid during the call it is passed to.
struct VehicleView {
    const traffic::VehicleSnapshot* snapshot;
    traffic::VehicleSnapshot::Index index;
};

/// The whole snapshot, as test_all(snapshot) receives it: numpy arrays that are read-only views
/// of the C++ arrays (no copy), valid during the call.
struct SnapshotView {
    const traffic::VehicleSnapshot* snapshot;
};

/// Adds the Vehicle and Snapshot classes to the module.
void bindSnapshotView(pybind11::module_& m);

}  // namespace sbsim::storyboard
