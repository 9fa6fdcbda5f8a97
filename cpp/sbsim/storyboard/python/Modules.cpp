// The modules story scripts import: `_sbsim` (re-exported by the `storyboard` package) and
// Artery's `timeline`. Registered with the interpreter when libsbsim loads.

#include <pybind11/embed.h>

#include "sbsim/python/SnapshotView.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/Bindings.h"

namespace py = pybind11;

namespace sbsim::storyboard {

using kernel::SimTime;

PYBIND11_EMBEDDED_MODULE(_sbsim, m) {
    m.doc() = "sbsim's storyboard API (Artery's names, with Pythonic aliases).";
    bindTypes(m);
    python::bindSnapshotView(m);
    bindVehicles(m);
    bindConditions(m);
    bindEffects(m);
    bindCriteria(m);
    bindBoard(m);
    bindWorld(m);
    bindScenario(m);
}

PYBIND11_EMBEDDED_MODULE(timeline, m) {
    m.doc() = "Artery's time helpers.";
    m.def(
        "seconds", [](const py::object& x) { return toSimTime(x, "seconds"); }, py::arg("x"));
    m.def(
        "milliseconds", [](const py::object& x) { return SimTime::fromSeconds(toNumber(x, "milliseconds") / 1000.0); },
        py::arg("x"));
}

}  // namespace sbsim::storyboard
