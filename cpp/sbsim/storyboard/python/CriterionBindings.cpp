#include <pybind11/stl.h>

#include <Eigen/Core>
#include <algorithm>
#include <memory>
#include <set>
#include <vector>

#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/criteria/KeepsLane.h"
#include "sbsim/storyboard/criteria/MaxSpeed.h"
#include "sbsim/storyboard/criteria/NoCollision.h"
#include "sbsim/storyboard/criteria/NoRedLightRunning.h"
#include "sbsim/storyboard/criteria/ReachedRegion.h"
#include "sbsim/storyboard/criteria/StoryActivated.h"
#include "sbsim/storyboard/criteria/WarnedBefore.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/Bindings.h"
#include "sbsim/storyboard/python/PythonCriterion.h"

namespace py = pybind11;

namespace sbsim::storyboard {

namespace {

/// `equipped_only` as a bool: any other value is a TypeError naming the criterion.
bool equippedOnly(const py::object& value, const char* criterion) {
    if (!py::isinstance<py::bool_>(value)) {
        throw py::type_error(std::string(criterion) + " equipped_only must be True or False, got " +
                             py::repr(value).cast<std::string>());
    }
    return value.cast<bool>();
}

VehicleSet vehicleSet(const py::object& ids, const py::object& equipped, const char* criterion) {
    const bool only = equippedOnly(equipped, criterion);
    if (ids.is_none()) return VehicleSet({}, only);
    const std::set<std::string> set = toIdSet(ids);
    return VehicleSet(std::vector<std::string>(set.begin(), set.end()), only);
}

}  // namespace

void bindCriteria(py::module_& m) {
    py::class_<Criterion, PythonCriterion, py::smart_holder>(m, "Criterion")
        .def(py::init<>())
        .def_property_readonly("name", &Criterion::name)
        .def("__repr__", &Criterion::describe)
        .doc() =
        "Base of custom criteria: override evaluate(self, run) -> bool | (passed, actual, expected); run.events is "
        "the event log (dicts), run.statistics the aggregates per name, run.activations per story.";
    py::class_<NoCollision, Criterion, py::smart_holder>(m, "NoCollision").def(py::init<>());
    py::class_<MaxSpeed, Criterion, py::smart_holder>(m, "MaxSpeed")
        .def(py::init([](const py::object& mps, const py::object& vehicles, const py::object& equipped) {
                 try {
                     return std::make_shared<MaxSpeed>(toNumber(mps, "MaxSpeed speed"),
                                                       vehicleSet(vehicles, equipped, "MaxSpeed"));
                 } catch (const std::invalid_argument& e) {
                     throw py::value_error(e.what());
                 }
             }),
             py::arg("mps"), py::arg("vehicles") = py::none(), py::arg("equipped_only") = false);
    py::class_<ReachedRegion, Criterion, py::smart_holder>(m, "ReachedRegion")
        .def(py::init([](const std::string& vehicle, const py::iterable& area, const py::object& by) {
                 std::vector<Eigen::Vector2d> vertices;
                 for (const py::handle p : area) vertices.push_back(toSumoPoint(p));
                 if (vertices.size() < 3) {
                     throw py::value_error("ReachedRegion needs an area of 3 or more points, got " +
                                           std::to_string(vertices.size()));
                 }
                 return std::make_shared<ReachedRegion>(vehicle, geometry::Polygon(std::move(vertices)),
                                                        toSimTime(by, "ReachedRegion by"));
             }),
             py::arg("vehicle"), py::arg("area"), py::arg("by"));
    py::class_<KeepsLane, Criterion, py::smart_holder>(m, "KeepsLane")
        .def(py::init([](const py::object& vehicles, const py::object& equipped) {
                 return std::make_shared<KeepsLane>(vehicleSet(vehicles, equipped, "KeepsLane"));
             }),
             py::arg("vehicles") = py::none(), py::arg("equipped_only") = false);
    py::class_<NoRedLightRunning, Criterion, py::smart_holder>(m, "NoRedLightRunning")
        .def(py::init([](const py::object& vehicles, const py::object& equipped) {
                 return std::make_shared<NoRedLightRunning>(vehicleSet(vehicles, equipped, "NoRedLightRunning"));
             }),
             py::arg("vehicles") = py::none(), py::arg("equipped_only") = false);
    py::class_<StoryActivated, Criterion, py::smart_holder>(m, "StoryActivated")
        .def(py::init([](const std::string& story, std::int64_t atLeast) {
                 try {
                     return std::make_shared<StoryActivated>(story, atLeast);
                 } catch (const std::invalid_argument& e) {
                     throw py::value_error(e.what());
                 }
             }),
             py::arg("story"), py::arg("at_least") = 1);
    py::class_<WarnedBefore, Criterion, py::smart_holder>(m, "WarnedBefore")
        .def(py::init([](const py::object& place, const py::object& cause, const py::object& seconds,
                         const py::object& since, const py::object& until, const py::object& equipped) {
                 const bool only = equippedOnly(equipped, "WarnedBefore");
                 std::optional<int> code;
                 if (!cause.is_none()) {
                     if (!py::isinstance<py::int_>(cause) || py::isinstance<py::bool_>(cause))
                         throw py::type_error("WarnedBefore cause must be a whole number (a cause code), got " +
                                              py::repr(cause).cast<std::string>());
                     code = static_cast<int>(std::clamp(cause.cast<long long>(), -1LL, 256LL));
                 }
                 const kernel::SimTime lead = toSimTime(seconds, "WarnedBefore seconds");
                 const kernel::SimTime from = toSimTime(since, "WarnedBefore since");
                 std::optional<kernel::SimTime> to;
                 if (!until.is_none()) to = toSimTime(until, "WarnedBefore until");
                 try {
                     if (py::isinstance<py::str>(place))
                         return WarnedBefore::onEdge(place.cast<std::string>(), code, lead, from, to, only);
                     if (!py::isinstance<py::iterable>(place))
                         throw py::type_error("WarnedBefore needs an edge id or an area (points), got " +
                                              py::repr(place).cast<std::string>());
                     std::vector<Eigen::Vector2d> vertices;
                     for (const py::handle p : place.cast<py::iterable>()) vertices.push_back(toSumoPoint(p));
                     if (vertices.size() < 3) {
                         throw py::value_error("WarnedBefore needs an area of 3 or more points, got " +
                                               std::to_string(vertices.size()));
                     }
                     return WarnedBefore::inArea(geometry::Polygon(std::move(vertices)), code, lead, from, to, only);
                 } catch (const std::invalid_argument& e) {
                     throw py::value_error(e.what());
                 }
             }),
             py::arg("area_or_edge"), py::arg("cause") = py::none(), py::arg("seconds") = 0, py::arg("since") = 0,
             py::arg("until") = py::none(), py::arg("equipped_only") = false);
}

}  // namespace sbsim::storyboard
