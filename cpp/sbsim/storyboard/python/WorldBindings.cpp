#include <fmt/format.h>
#include <pybind11/stl.h>

#include "sbsim/storyboard/WorldStory.h"
#include "sbsim/storyboard/effects/CloseRoadEffect.h"
#include "sbsim/storyboard/effects/RemoveVehicleEffect.h"
#include "sbsim/storyboard/effects/SpawnEffect.h"
#include "sbsim/storyboard/effects/TrafficLightEffect.h"
#include "sbsim/storyboard/effects/TrafficLightPhaseEffect.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/Bindings.h"

namespace py = pybind11;

namespace sbsim::storyboard {

namespace {

std::string textOf(const py::handle& value) { return py::repr(value).cast<std::string>(); }

/// One edge id or an iterable of them, in the given order.
std::vector<std::string> toEdges(const py::handle& value, const char* what) {
    const auto fail = [&] {
        return py::type_error(fmt::format("{} must be an edge id or a list of edge ids, got {}", what, textOf(value)));
    };
    if (py::isinstance<py::str>(value)) return {value.cast<std::string>()};
    if (!py::isinstance<py::iterable>(value) || py::isinstance<py::bytes>(value)) throw fail();
    std::vector<std::string> out;
    for (const py::handle e : py::iter(value)) {
        if (!py::isinstance<py::str>(e)) throw fail();
        out.push_back(e.cast<std::string>());
    }
    return out;
}

/// None, a number (`whole`: a whole number >= 0) or one of SUMO's keywords, as SUMO's string.
std::optional<std::string> toDepart(const py::object& value, const char* what, bool whole) {
    if (value.is_none()) return std::nullopt;
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (whole) {
        if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value) || value.cast<long long>() < 0) {
            throw py::type_error(
                fmt::format("{} must be a lane index >= 0 or a SUMO keyword, got {}", what, textOf(value)));
        }
        return std::to_string(value.cast<long long>());
    }
    return fmt::format("{}", toNumber(value, what));
}

std::string optionalEdge(const py::object& value, const char* what) {
    if (value.is_none()) return {};
    if (!py::isinstance<py::str>(value))
        throw py::type_error(fmt::format("{} must be an edge id, got {}", what, textOf(value)));
    return value.cast<std::string>();
}

}  // namespace

void bindWorld(py::module_& m) {
    py::class_<WorldEffect, py::smart_holder>(m, "WorldEffect").doc() =
        "Base of the effects on the network a WorldStory takes (CloseRoadEffect, SpawnEffect, TrafficLightEffect).";
    py::class_<CloseRoadEffect, WorldEffect, py::smart_holder>(m, "CloseRoadEffect")
        .def(py::init([](const py::object& edges) {
                 return std::make_shared<CloseRoadEffect>(toEdges(edges, "CloseRoadEffect edge_ids"));
             }),
             py::arg("edge_ids"))
        .def_property_readonly("edge_ids", &CloseRoadEffect::edges);
    py::class_<SpawnEffect, WorldEffect, py::smart_holder>(m, "SpawnEffect")
        .def(py::init([](const std::string& id, const py::object& route, const py::object& from, const py::object& to,
                         const std::optional<std::string>& type, const py::object& lane, const py::object& position,
                         const py::object& speed) {
                 SpawnEffect::Spec spec;
                 spec.id = id;
                 if (!route.is_none()) spec.route = toEdges(route, "SpawnEffect route");
                 spec.from = optionalEdge(from, "SpawnEffect from_edge");
                 spec.to = optionalEdge(to, "SpawnEffect to_edge");
                 spec.type = type;
                 spec.lane = toDepart(lane, "SpawnEffect lane", true);
                 spec.position = toDepart(position, "SpawnEffect position", false);
                 spec.speed = toDepart(speed, "SpawnEffect speed", false);
                 return std::make_shared<SpawnEffect>(std::move(spec));
             }),
             py::arg("id"), py::arg("route") = py::none(), py::arg("from_edge") = py::none(),
             py::arg("to_edge") = py::none(), py::arg("type") = py::none(), py::arg("lane") = py::none(),
             py::arg("position") = py::none(), py::arg("speed") = py::none())
        .def_property_readonly("id", [](const SpawnEffect& e) { return e.spec().id; });
    py::class_<RemoveVehicleEffect, WorldEffect, py::smart_holder>(m, "RemoveVehicleEffect")
        .def(py::init<std::string>(), py::arg("id"))
        .def_property_readonly("id", &RemoveVehicleEffect::id);
    py::class_<TrafficLightEffect, WorldEffect, py::smart_holder>(m, "TrafficLightEffect")
        .def(py::init<std::string, std::string, std::vector<int>, bool>(), py::arg("tls_id"), py::arg("state"),
             py::arg("links") = std::vector<int>{}, py::arg("keep") = false)
        .def_property_readonly("tls_id", &TrafficLightEffect::tls)
        .def_property_readonly("state", &TrafficLightEffect::state)
        .def_property_readonly("links", &TrafficLightEffect::links)
        .def_property_readonly("keep", &TrafficLightEffect::keep);
    py::class_<TrafficLightPhaseEffect, WorldEffect, py::smart_holder>(m, "TrafficLightPhaseEffect")
        .def(py::init<std::string, int>(), py::arg("tls_id"), py::arg("phase"))
        .def_property_readonly("tls_id", &TrafficLightPhaseEffect::tls)
        .def_property_readonly("phase", &TrafficLightPhaseEffect::phase);

    py::class_<WorldStory, Story, py::smart_holder>(m, "WorldStory")
        .def(py::init([](ConditionPtr condition, const py::object& effects, std::optional<std::string> name) {
                 if (!condition) throw py::type_error("WorldStory needs a condition, got None");
                 std::vector<WorldEffectPtr> list;
                 if (!effects.is_none()) {
                     for (const py::handle e : py::iter(effects)) {
                         if (!py::isinstance<WorldEffect>(e)) {
                             throw py::type_error(
                                 "WorldStory effects must be world effects (CloseRoadEffect, SpawnEffect, "
                                 "TrafficLightEffect), got " +
                                 textOf(e) + (py::isinstance<Effect>(e) ? ": per-vehicle effects go in a Story" : ""));
                         }
                         list.push_back(e.cast<WorldEffectPtr>());
                     }
                 }
                 return std::make_shared<WorldStory>(std::move(condition), std::move(list), std::move(name));
             }),
             py::arg("condition"), py::arg("effects") = py::none(), py::arg("name") = py::none());
}

}  // namespace sbsim::storyboard
