#pragma once

#include <pybind11/pybind11.h>

namespace sbsim::storyboard {

// The story API's module `_sbsim` (re-exported by the `storyboard` package), one domain per file;
// Modules.cpp assembles them. Thin on purpose: argument conversion here, semantics in C++.

/// SimTime, Coord and RandomNumberGenerator.
void bindTypes(pybind11::module_& m);
/// VehicleController, what custom effects command.
void bindVehicles(pybind11::module_& m);
/// Condition (the base of custom ones) and the built-in conditions.
void bindConditions(pybind11::module_& m);
/// Effect (the base of custom ones) and the built-in effects.
void bindEffects(pybind11::module_& m);
/// Criterion (the base of custom ones) and the built-in criteria.
void bindCriteria(pybind11::module_& m);
/// Story and the `board` scripts receive.
void bindBoard(pybind11::module_& m);
/// WorldStory and the world effects (after bindBoard: a WorldStory is a Story).
void bindWorld(pybind11::module_& m);
/// ScenarioMachine, OpenSCENARIO's storyboard state machine (its conditions: bindConditions), and
/// ScenarioParameters with ParameterCondition and ParameterEffect (after bindConditions, bindWorld).
void bindScenario(pybind11::module_& m);

}  // namespace sbsim::storyboard
