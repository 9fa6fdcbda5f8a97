#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include <limits>

#include "sbsim/storyboard/effects/ColorEffect.h"
#include "sbsim/storyboard/effects/EmergencyStopEffect.h"
#include "sbsim/storyboard/effects/LaneEffect.h"
#include "sbsim/storyboard/effects/RouteEffect.h"
#include "sbsim/storyboard/effects/SetSpeedEffect.h"
#include "sbsim/storyboard/effects/SignalEffect.h"
#include "sbsim/storyboard/effects/SpeedEffect.h"
#include "sbsim/storyboard/effects/SpeedFactorEffect.h"
#include "sbsim/storyboard/effects/StopEffect.h"
#include "sbsim/storyboard/effects/TypeEffect.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/PythonEffect.h"

namespace py = pybind11;

namespace sbsim::storyboard {

namespace {

/// (r, g, b) or (r, g, b, a), each a whole number 0..255.
traffic::Color toColor(const py::handle& value) {
    const auto fail = [&] {
        return py::type_error("ColorEffect needs (r, g, b) or (r, g, b, a) with whole numbers 0..255, got " +
                              py::repr(value).cast<std::string>());
    };
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value)) throw fail();
    const auto seq = py::reinterpret_borrow<py::sequence>(value);
    if (seq.size() != 3 && seq.size() != 4) throw fail();
    std::uint8_t parts[4] = {0, 0, 0, 255};
    for (std::size_t k = 0; k < seq.size(); ++k) {
        const py::handle p = seq[k];
        if (!py::isinstance<py::int_>(p) || py::isinstance<py::bool_>(p)) throw fail();
        const long long v = p.cast<long long>();
        if (v < 0 || v > 255) throw py::value_error("ColorEffect components must be 0..255, got " + std::to_string(v));
        parts[k] = static_cast<std::uint8_t>(v);
    }
    return {parts[0], parts[1], parts[2], parts[3]};
}

/// A lane index: a whole number 0..INT_MAX.
int toLaneIndex(const py::object& value) {
    if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
        throw py::type_error("LaneEffect needs a whole lane index, got " + py::repr(value).cast<std::string>());
    if (value < py::int_(0) || value > py::int_(std::numeric_limits<int>::max()))
        throw py::value_error("LaneEffect needs a lane index >= 0, got " + py::repr(value).cast<std::string>());
    return value.cast<int>();
}

/// An edge id: a non-empty str.
std::string toEdge(const py::handle& value) {
    if (!py::isinstance<py::str>(value))
        throw py::type_error("RouteEffect edges must be edge ids (str), got " + py::repr(value).cast<std::string>());
    std::string edge = value.cast<std::string>();
    if (edge.empty()) throw py::value_error("RouteEffect edges must not be empty strings");
    return edge;
}

std::shared_ptr<RouteEffect> makeRouteEffect(const py::object& targetEdge, const py::object& via) {
    if (targetEdge.is_none() == via.is_none())
        throw py::value_error("RouteEffect needs either target_edge or via=[edges], not both or neither");
    if (!targetEdge.is_none()) return std::make_shared<RouteEffect>(toEdge(targetEdge), std::vector<std::string>{});
    if (!py::isinstance<py::iterable>(via) || py::isinstance<py::str>(via))
        throw py::type_error("RouteEffect via must be a list of edge ids, got " + py::repr(via).cast<std::string>());
    std::vector<std::string> edges;
    for (const py::handle edge : via) edges.push_back(toEdge(edge));
    if (edges.empty()) throw py::value_error("RouteEffect via needs at least one edge");
    return std::make_shared<RouteEffect>(std::nullopt, std::move(edges));
}

}  // namespace

void bindEffects(py::module_& m) {
    py::class_<Effect, PythonEffect, py::smart_holder>(m, "Effect").def(py::init<>()).doc() =
        "Base of custom effects: override apply(self, vehicle) and remove(self, vehicle); "
        "vehicle is a VehicleController.";
    py::class_<SpeedEffect, Effect, py::smart_holder>(m, "SpeedEffect")
        .def(py::init([](const py::object& mps, const py::object& over) {
                 return std::make_shared<SpeedEffect>(
                     toNumber(mps, "SpeedEffect speed"),
                     over.is_none() ? 0.0 : toSimTime(over, "SpeedEffect over").seconds());
             }),
             py::arg("mps"), py::arg("over") = py::none())
        .def_property_readonly("over", &SpeedEffect::over)
        .def_property_readonly("speed", &SpeedEffect::speed);
    py::class_<StopEffect, Effect, py::smart_holder>(m, "StopEffect").def(py::init<>());
    py::class_<SetSpeedEffect, Effect, py::smart_holder>(m, "SetSpeedEffect")
        .def(py::init([](const py::object& mps) {
                 return std::make_shared<SetSpeedEffect>(toNumber(mps, "SetSpeedEffect speed"));
             }),
             py::arg("mps"))
        .def_property_readonly("speed", &SetSpeedEffect::speed);
    py::class_<EmergencyStopEffect, Effect, py::smart_holder>(m, "EmergencyStopEffect").def(py::init<>());
    py::class_<SignalEffect, Effect, py::smart_holder>(m, "SignalEffect")
        .def(py::init<std::string, std::optional<std::string>>(), py::arg("cause"), py::arg("on_exit") = py::none())
        .def_property_readonly("cause", &SignalEffect::cause)
        .def_property_readonly("on_exit", &SignalEffect::onExit);
    py::class_<SpeedFactorEffect, Effect, py::smart_holder>(m, "SpeedFactorEffect")
        .def(py::init([](const py::object& factor) {
                 const double f = toNumber(factor, "SpeedFactorEffect factor");
                 if (f <= 0) throw py::value_error("SpeedFactorEffect needs a factor > 0");
                 return std::make_shared<SpeedFactorEffect>(f);
             }),
             py::arg("factor"))
        .def_property_readonly("factor", &SpeedFactorEffect::factor);
    py::class_<TypeEffect, Effect, py::smart_holder>(m, "TypeEffect")
        .def(py::init([](const std::string& typeId) {
                 if (typeId.empty()) throw py::value_error("TypeEffect needs a vehicle type id");
                 return std::make_shared<TypeEffect>(typeId);
             }),
             py::arg("type_id"))
        .def_property_readonly("type_id", &TypeEffect::typeId);
    py::class_<ColorEffect, Effect, py::smart_holder>(m, "ColorEffect")
        .def(py::init([](const py::object& color) { return std::make_shared<ColorEffect>(toColor(color)); }),
             py::arg("color"))
        .def_property_readonly("color", [](const ColorEffect& e) {
            const traffic::Color& c = e.color();
            return py::make_tuple(c.r, c.g, c.b, c.a);
        });
    py::class_<LaneEffect, Effect, py::smart_holder>(m, "LaneEffect")
        .def(py::init([](const py::object& index) { return std::make_shared<LaneEffect>(toLaneIndex(index)); }),
             py::arg("lane_index"))
        .def_property_readonly("lane_index", &LaneEffect::laneIndex);
    py::class_<RouteEffect, Effect, py::smart_holder>(m, "RouteEffect")
        .def(py::init(&makeRouteEffect), py::arg("target_edge") = py::none(), py::kw_only(),
             py::arg("via") = py::none())
        .def_property_readonly("target_edge", [](const RouteEffect& e) { return e.route().target; })
        .def_property_readonly("via", [](const RouteEffect& e) { return e.route().via; });
    // Artery's names: its effects derive from EffectFactory; and its older factory names.
    m.attr("EffectFactory") = m.attr("Effect");
    m.attr("SpeedEffectFactory") = m.attr("SpeedEffect");
    m.attr("StopEffectFactory") = m.attr("StopEffect");
    m.attr("SignalEffectFactory") = m.attr("SignalEffect");
}

}  // namespace sbsim::storyboard
