#pragma once

#include <pybind11/pybind11.h>

#include <memory>

#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::python {

/// Says whether the step a view was made for is still the current one. Scripts may keep a view
/// past its call; the snapshot behind it changes (and its arrays move) at the next step, so a
/// view of an old step raises instead of reading stale or freed memory.
using StepValidity = std::shared_ptr<const bool>;

/// One vehicle of the current snapshot, as custom conditions' test(vehicle) receives it.
/// Usable during the step it was passed in; afterwards every read raises.
struct VehicleView {
    const traffic::VehicleSnapshot* snapshot;
    traffic::VehicleSnapshot::Index index;
    StepValidity valid;
};

/// The whole snapshot, as test_all(snapshot) receives it. Its numpy arrays are read-only copies,
/// made on first access and then cached for the call, so they stay valid when kept; the view
/// itself raises when read after its step.
struct SnapshotView {
    const traffic::VehicleSnapshot* snapshot;
    StepValidity valid;
    pybind11::dict columns;  ///< copies made so far, by attribute name
};

/// Adds the Vehicle and Snapshot classes to the module.
void bindSnapshotView(pybind11::module_& m);

}  // namespace sbsim::python
