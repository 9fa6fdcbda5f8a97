#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include <limits>

#include "sbsim/storyboard/effects/ColorEffect.h"
#include "sbsim/storyboard/effects/EmergencyStopEffect.h"
#include "sbsim/storyboard/effects/LaneChangeEffect.h"
#include "sbsim/storyboard/effects/LaneEffect.h"
#include "sbsim/storyboard/effects/LaneOffsetEffect.h"
#include "sbsim/storyboard/effects/RouteEffect.h"
#include "sbsim/storyboard/effects/SetSpeedEffect.h"
#include "sbsim/storyboard/effects/SignalEffect.h"
#include "sbsim/storyboard/effects/SpeedChangeEffect.h"
#include "sbsim/storyboard/effects/SpeedEffect.h"
#include "sbsim/storyboard/effects/SpeedFactorEffect.h"
#include "sbsim/storyboard/effects/StopEffect.h"
#include "sbsim/storyboard/effects/TeleportEffect.h"
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

std::vector<std::string> toEdges(const py::object& edges, const char* who) {
    if (!py::isinstance<py::iterable>(edges) || py::isinstance<py::str>(edges))
        throw py::type_error(std::string(who) + " must be a list of edge ids, got " +
                             py::repr(edges).cast<std::string>());
    std::vector<std::string> out;
    for (const py::handle edge : edges) out.push_back(toEdge(edge));
    return out;
}

std::shared_ptr<RouteEffect> makeRouteEffect(const py::object& targetEdge, const py::object& via, bool keep) {
    if (keep) {
        if (targetEdge.is_none() && via.is_none())
            throw py::value_error("RouteEffect needs target_edge or via=[edges]");
        std::vector<std::string> edges = via.is_none() ? std::vector<std::string>{} : toEdges(via, "RouteEffect via");
        std::optional<std::string> target;
        if (!targetEdge.is_none()) target = toEdge(targetEdge);
        if (!target && edges.empty()) throw py::value_error("RouteEffect via needs at least one edge");
        return std::make_shared<RouteEffect>(std::move(target), std::move(edges), true);
    }
    if (targetEdge.is_none() == via.is_none())
        throw py::value_error("RouteEffect needs either target_edge or via=[edges], not both or neither");
    if (!targetEdge.is_none()) return std::make_shared<RouteEffect>(toEdge(targetEdge), std::vector<std::string>{});
    std::vector<std::string> edges = toEdges(via, "RouteEffect via");
    if (edges.empty()) throw py::value_error("RouteEffect via needs at least one edge");
    return std::make_shared<RouteEffect>(std::nullopt, std::move(edges));
}

std::shared_ptr<TeleportEffect> makeTeleportEffect(const py::object& edge, const py::object& lane,
                                                   const py::object& position,
                                                   const std::optional<std::string>& relativeTo,
                                                   const py::object& onward) {
    if (!py::isinstance<py::int_>(lane) || py::isinstance<py::bool_>(lane))
        throw py::type_error("TeleportEffect needs a whole lane number, got " + py::repr(lane).cast<std::string>());
    TeleportEffect::Target target;
    target.lane = lane.cast<int>();
    target.position = toNumber(position, "TeleportEffect position");
    target.relativeTo = relativeTo;
    if (relativeTo) {
        if (relativeTo->empty()) throw py::value_error("TeleportEffect relative_to needs a vehicle id");
        if (!edge.is_none()) throw py::value_error("TeleportEffect: an edge or relative_to=vehicle, not both");
    } else {
        if (edge.is_none()) throw py::value_error("TeleportEffect needs an edge (or relative_to=vehicle)");
        target.edge = toEdge(edge);
        if (target.lane < 0) throw py::value_error("TeleportEffect needs a lane index >= 0");
        if (target.position < 0) throw py::value_error("TeleportEffect needs a position >= 0 m");
    }
    std::vector<std::string> route =
        onward.is_none() ? std::vector<std::string>{} : toEdges(onward, "TeleportEffect onward");
    if (!route.empty() && route.front() != target.edge)
        throw py::value_error("TeleportEffect onward must start on the target edge");
    return std::make_shared<TeleportEffect>(std::move(target), std::move(route));
}

/// OpenSCENARIO's TransitionDynamics: shape "step" | "linear" | "cubic" | "sinusoidal", dimension
/// "time" | "distance" | "rate" (or those given), value.
traffic::Transition toTransition(const std::string& shape, const std::string& dimension, const py::object& value,
                                 const char* who) {
    const auto s = traffic::Transition::shapeNamed(shape);
    if (!s) {
        throw py::value_error(std::string(who) + " shape must be 'step', 'linear', 'cubic' or 'sinusoidal', got '" +
                              shape + "'");
    }
    const auto d = traffic::Transition::dimensionNamed(dimension);
    if (!d) {
        throw py::value_error(std::string(who) + " dimension must be 'time', 'distance' or 'rate', got '" + dimension +
                              "'");
    }
    const std::string what = std::string(who) + " value";
    const double v = toNumber(value, what.c_str());
    if (v < 0) throw py::value_error(what + " must be >= 0");
    if (*s != traffic::Transition::Shape::Step && v == 0)
        throw py::value_error(what + " must be > 0 for a '" + shape + "' transition");
    return {*s, *d, v};
}

std::shared_ptr<SpeedChangeEffect> makeSpeedChangeEffect(const py::object& target, const std::string& shape,
                                                         const std::string& dimension, const py::object& value,
                                                         const std::optional<std::string>& relativeTo,
                                                         const std::string& valueType, bool continuous, bool safeGap,
                                                         bool keep) {
    const double t = toNumber(target, "SpeedChangeEffect target");
    const traffic::Transition dynamics = toTransition(shape, dimension, value, "SpeedChangeEffect");
    traffic::SpeedTarget::Kind kind = traffic::SpeedTarget::Kind::Delta;
    if (valueType == "factor") {
        kind = traffic::SpeedTarget::Kind::Factor;
    } else if (valueType != "delta") {
        throw py::value_error("SpeedChangeEffect value_type must be 'delta' or 'factor', got '" + valueType + "'");
    }
    if (!relativeTo && (valueType != "delta" || continuous))
        throw py::value_error("SpeedChangeEffect value_type and continuous need relative_to, the vehicle followed");
    if (relativeTo && relativeTo->empty()) throw py::value_error("SpeedChangeEffect relative_to needs a vehicle id");
    if (!relativeTo && t < 0) throw py::value_error("SpeedChangeEffect needs a target speed >= 0 m/s");
    if (kind == traffic::SpeedTarget::Kind::Factor && t < 0)
        throw py::value_error("SpeedChangeEffect needs a factor >= 0");
    return std::make_shared<SpeedChangeEffect>(t, dynamics, relativeTo, kind, continuous, safeGap, keep);
}

std::shared_ptr<LaneChangeEffect> makeLaneChangeEffect(const py::object& lane, const std::string& shape,
                                                       const std::string& dimension, const py::object& value,
                                                       bool relative, const std::optional<std::string>& relativeTo,
                                                       const py::object& offset) {
    if (!py::isinstance<py::int_>(lane) || py::isinstance<py::bool_>(lane))
        throw py::type_error("LaneChangeEffect needs a whole lane number, got " + py::repr(lane).cast<std::string>());
    const int index = lane.cast<int>();
    if (relative && relativeTo)
        throw py::value_error("LaneChangeEffect: relative=True (own lane) or relative_to=vehicle, not both");
    if (relativeTo && relativeTo->empty()) throw py::value_error("LaneChangeEffect relative_to needs a vehicle id");
    using Relative = LaneChangeEffect::Relative;
    const Relative kind = relativeTo ? Relative::Vehicle : relative ? Relative::Self : Relative::Absolute;
    if (kind == Relative::Absolute && index < 0)
        throw py::value_error("LaneChangeEffect needs a lane index >= 0 (or relative=True), got " +
                              std::to_string(index));
    return std::make_shared<LaneChangeEffect>(index, toTransition(shape, dimension, value, "LaneChangeEffect"), kind,
                                              relativeTo, toNumber(offset, "LaneChangeEffect offset"));
}

std::shared_ptr<LaneOffsetEffect> makeLaneOffsetEffect(const py::object& offset, const std::string& shape,
                                                       const py::object& duration, const py::object& maxLateralAcc,
                                                       const std::optional<std::string>& relativeTo, bool continuous) {
    const double o = toNumber(offset, "LaneOffsetEffect offset");
    if (relativeTo && relativeTo->empty()) throw py::value_error("LaneOffsetEffect relative_to needs a vehicle id");
    if (duration.is_none() == maxLateralAcc.is_none() && shape != "step")
        throw py::value_error("LaneOffsetEffect needs duration=seconds or max_lateral_acc=m/s², one of them");
    if (!maxLateralAcc.is_none()) {
        const double a = toNumber(maxLateralAcc, "LaneOffsetEffect max_lateral_acc");
        if (a <= 0) throw py::value_error("LaneOffsetEffect max_lateral_acc must be > 0");
        return std::make_shared<LaneOffsetEffect>(o, toTransition(shape, "time", py::float_(1.0), "LaneOffsetEffect"),
                                                  a, relativeTo, continuous);
    }
    const py::object seconds = duration.is_none() ? py::object(py::float_(0.0)) : duration;
    return std::make_shared<LaneOffsetEffect>(o, toTransition(shape, "time", seconds, "LaneOffsetEffect"), std::nullopt,
                                              relativeTo, continuous);
}

std::string shapeName(const traffic::Transition& t) { return std::string(traffic::Transition::name(t.shape)); }
std::string dimensionName(const traffic::Transition& t) { return std::string(traffic::Transition::name(t.dimension)); }

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
             py::arg("via") = py::none(), py::arg("keep") = false)
        .def_property_readonly("target_edge", [](const RouteEffect& e) { return e.route().target; })
        .def_property_readonly("via", [](const RouteEffect& e) { return e.route().via; })
        .def_property_readonly("keep", &RouteEffect::keep);
    py::class_<TeleportEffect, Effect, py::smart_holder>(m, "TeleportEffect")
        .def(py::init(&makeTeleportEffect), py::arg("edge") = py::none(), py::arg("lane") = 0,
             py::arg("position") = 0.0, py::kw_only(), py::arg("relative_to") = py::none(),
             py::arg("onward") = py::none())
        .def_property_readonly("edge",
                               [](const TeleportEffect& e) -> std::optional<std::string> {
                                   if (e.target().edge.empty()) return std::nullopt;
                                   return e.target().edge;
                               })
        .def_property_readonly("lane", [](const TeleportEffect& e) { return e.target().lane; })
        .def_property_readonly("position", [](const TeleportEffect& e) { return e.target().position; })
        .def_property_readonly("relative_to", [](const TeleportEffect& e) { return e.target().relativeTo; })
        .def_property_readonly("onward", &TeleportEffect::onward);
    py::class_<SpeedChangeEffect, Effect, py::smart_holder>(m, "SpeedChangeEffect")
        .def(py::init(&makeSpeedChangeEffect), py::arg("target"), py::arg("shape") = "step",
             py::arg("dimension") = "time", py::arg("value") = 0.0, py::kw_only(), py::arg("relative_to") = py::none(),
             py::arg("value_type") = "delta", py::arg("continuous") = false, py::arg("safe_gap") = false,
             py::arg("keep") = false)
        .def_property_readonly("target", &SpeedChangeEffect::target)
        .def_property_readonly(
            "shape",
            [](const SpeedChangeEffect& e) { return std::string(traffic::Transition::name(e.dynamics().shape)); })
        .def_property_readonly(
            "dimension",
            [](const SpeedChangeEffect& e) { return std::string(traffic::Transition::name(e.dynamics().dimension)); })
        .def_property_readonly("value", [](const SpeedChangeEffect& e) { return e.dynamics().value; })
        .def_property_readonly("relative_to", &SpeedChangeEffect::relativeTo)
        .def_property_readonly("value_type",
                               [](const SpeedChangeEffect& e) {
                                   return e.kind() == traffic::SpeedTarget::Kind::Factor ? "factor" : "delta";
                               })
        .def_property_readonly("continuous", &SpeedChangeEffect::continuous)
        .def_property_readonly("safe_gap", &SpeedChangeEffect::safeGap)
        .def_property_readonly("keep", &SpeedChangeEffect::keep);
    py::class_<LaneChangeEffect, Effect, py::smart_holder>(m, "LaneChangeEffect")
        .def(py::init(&makeLaneChangeEffect), py::arg("lane"), py::arg("shape") = "step", py::arg("dimension") = "time",
             py::arg("value") = 0.0, py::kw_only(), py::arg("relative") = false, py::arg("relative_to") = py::none(),
             py::arg("offset") = 0.0)
        .def_property_readonly("lane", &LaneChangeEffect::lane)
        .def_property_readonly("shape", [](const LaneChangeEffect& e) { return shapeName(e.dynamics()); })
        .def_property_readonly("dimension", [](const LaneChangeEffect& e) { return dimensionName(e.dynamics()); })
        .def_property_readonly("value", [](const LaneChangeEffect& e) { return e.dynamics().value; })
        .def_property_readonly(
            "relative", [](const LaneChangeEffect& e) { return e.relative() == LaneChangeEffect::Relative::Self; })
        .def_property_readonly("relative_to", &LaneChangeEffect::relativeTo)
        .def_property_readonly("offset", &LaneChangeEffect::offset);
    py::class_<LaneOffsetEffect, Effect, py::smart_holder>(m, "LaneOffsetEffect")
        .def(py::init(&makeLaneOffsetEffect), py::arg("offset"), py::arg("shape") = "step", py::kw_only(),
             py::arg("duration") = py::none(), py::arg("max_lateral_acc") = py::none(),
             py::arg("relative_to") = py::none(), py::arg("continuous") = false)
        .def_property_readonly("offset", &LaneOffsetEffect::offset)
        .def_property_readonly("relative_to", &LaneOffsetEffect::relativeTo)
        .def_property_readonly("continuous", &LaneOffsetEffect::continuous)
        .def_property_readonly("shape", [](const LaneOffsetEffect& e) { return shapeName(e.dynamics()); })
        .def_property_readonly("duration",
                               [](const LaneOffsetEffect& e) -> std::optional<double> {
                                   if (e.maxLateralAcceleration()) return std::nullopt;
                                   return e.dynamics().value;
                               })
        .def_property_readonly("max_lateral_acc", &LaneOffsetEffect::maxLateralAcceleration);
    // Artery's names: its effects derive from EffectFactory; and its older factory names.
    m.attr("EffectFactory") = m.attr("Effect");
    m.attr("SpeedEffectFactory") = m.attr("SpeedEffect");
    m.attr("StopEffectFactory") = m.attr("StopEffect");
    m.attr("SignalEffectFactory") = m.attr("SignalEffect");
}

}  // namespace sbsim::storyboard
