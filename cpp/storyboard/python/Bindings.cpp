// The story API seen by Python: module `_sbsim` (re-exported by the `storyboard` package) and
// Artery's `timeline`. Thin on purpose: argument conversion here, semantics in the C++ classes.

#include <pybind11/embed.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/StoryError.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/DeferringCondition.h"
#include "sbsim/storyboard/conditions/LikelihoodCondition.h"
#include "sbsim/storyboard/conditions/LimitCondition.h"
#include "sbsim/storyboard/conditions/OrCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/SpeedDifferenceCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/conditions/TtcCondition.h"
#include "sbsim/storyboard/effects/EmergencyStopEffect.h"
#include "sbsim/storyboard/effects/SignalEffect.h"
#include "sbsim/storyboard/effects/SpeedEffect.h"
#include "sbsim/storyboard/effects/StopEffect.h"
#include "sbsim/storyboard/python/PythonCondition.h"
#include "sbsim/storyboard/python/PythonEffect.h"
#include "sbsim/storyboard/python/ScriptContext.h"
#include "sbsim/storyboard/python/SnapshotView.h"

namespace py = pybind11;
using sbsim::kernel::SimTime;
using sbsim::traffic::VehicleController;

namespace sbsim::storyboard {

namespace {

/// Artery's Coord: a point in the canvas frame.
struct Coord {
    double x = 0;
    double y = 0;
};

/// The `board` object scripts receive.
struct BoardHandle {
    Storyboard& board() const {
        Storyboard* b = ScriptContext::current().board;
        if (b == nullptr) throw std::runtime_error("the storyboard is only available while sbsim runs a story");
        return *b;
    }
};

/// Seconds as SimTime from a SimTime or a plain number (Artery scripts pass both).
SimTime toSimTime(const py::handle& value, const char* what) {
    if (py::isinstance<SimTime>(value)) return value.cast<SimTime>();
    if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))) {
        throw py::type_error(std::string(what) + " must be a SimTime or a number of seconds, got " +
                             py::str(py::type::of(value).attr("__name__")).cast<std::string>());
    }
    const double seconds = value.cast<double>();
    if (!std::isfinite(seconds)) throw py::value_error(std::string(what) + " must be finite");
    return SimTime::fromSeconds(seconds);
}

double toNumber(const py::handle& value, const char* what) {
    if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))) {
        throw py::type_error(std::string(what) + " must be a number, got " +
                             py::str(py::type::of(value).attr("__name__")).cast<std::string>() + " " +
                             py::repr(value).cast<std::string>());
    }
    const double v = value.cast<double>();
    if (!std::isfinite(v)) throw py::value_error(std::string(what) + " must be finite");
    return v;
}

/// Coord → SUMO via the canvas frame; a plain (x, y) pair is already SUMO's.
Eigen::Vector2d toSumoPoint(const py::handle& point) {
    if (py::isinstance<Coord>(point)) {
        const Coord c = point.cast<Coord>();
        return ScriptContext::current().frame.toSumo({c.x, c.y});
    }
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(point);
    if (!py::isinstance<py::sequence>(point) || py::len(pair) != 2) {
        throw py::type_error("polygon points must be storyboard.Coord or (x, y) pairs, got " +
                             py::repr(point).cast<std::string>());
    }
    return {toNumber(pair[0], "x"), toNumber(pair[1], "y")};
}

std::set<std::string> toIdSet(const py::handle& ids) {
    if (py::isinstance<py::str>(ids)) return {ids.cast<std::string>()};
    std::set<std::string> out;
    for (const py::handle id : py::iter(ids)) {
        if (!py::isinstance<py::str>(id))
            throw py::type_error("vehicle ids must be strings, got " + py::repr(id).cast<std::string>());
        out.insert(id.cast<std::string>());
    }
    return out;
}

std::optional<double> optionalDistance(const py::object& distance) {
    if (distance.is_none()) return std::nullopt;
    const double d = toNumber(distance, "distance");
    if (d < 0) throw py::value_error("distance must be >= 0 m");
    return d;
}

template <typename Condition, typename Class>
void bindSpeedDifference(Class&& cls) {
    cls.def(py::init([](const py::object& delta, const py::object& distance) {
                return std::make_shared<Condition>(toNumber(delta, "delta"), optionalDistance(distance));
            }),
            py::arg("delta"), py::arg("distance") = py::none());
}

}  // namespace

PYBIND11_EMBEDDED_MODULE(_sbsim, m) {
    m.doc() = "sbsim's storyboard API (Artery's names, with Pythonic aliases).";

    py::class_<SimTime>(m, "SimTime")
        .def(py::init([](const py::object& seconds) { return toSimTime(seconds, "SimTime"); }),
             py::arg("seconds") = 0.0)
        .def_property_readonly("seconds", &SimTime::seconds)
        .def("__float__", &SimTime::seconds)
        .def("__add__", [](const SimTime& a, const py::object& b) { return a + toSimTime(b, "operand"); })
        .def("__radd__", [](const SimTime& a, const py::object& b) { return toSimTime(b, "operand") + a; })
        .def("__sub__", [](const SimTime& a, const py::object& b) { return a - toSimTime(b, "operand"); })
        .def("__rsub__", [](const SimTime& a, const py::object& b) { return toSimTime(b, "operand") - a; })
        .def("__eq__",
             [](const SimTime& a, const py::object& b) { return py::isinstance<SimTime>(b) && a == b.cast<SimTime>(); })
        .def("__lt__", [](const SimTime& a, const py::object& b) { return a < toSimTime(b, "operand"); })
        .def("__le__", [](const SimTime& a, const py::object& b) { return a <= toSimTime(b, "operand"); })
        .def("__gt__", [](const SimTime& a, const py::object& b) { return a > toSimTime(b, "operand"); })
        .def("__ge__", [](const SimTime& a, const py::object& b) { return a >= toSimTime(b, "operand"); })
        .def("__hash__", [](const SimTime& t) { return std::hash<SimTime::rep>()(t.raw()); })
        .def("__repr__", [](const SimTime& t) { return "SimTime(" + t.str() + ")"; });

    py::class_<Coord>(m, "Coord")
        .def(py::init([](const py::object& x, const py::object& y) {
                 return Coord{toNumber(x, "x"), toNumber(y, "y")};
             }),
             py::arg("x"), py::arg("y"))
        .def_readonly("x", &Coord::x)
        .def_readonly("y", &Coord::y)
        .def("__repr__", [](const Coord& c) {
            return "Coord(" + py::repr(py::float_(c.x)).cast<std::string>() + ", " +
                   py::repr(py::float_(c.y)).cast<std::string>() + ")";
        });

    py::class_<kernel::RandomStream, py::smart_holder>(m, "RandomNumberGenerator")
        .def_property_readonly("index", &kernel::RandomStream::index)
        .def(
            "uniform", [](kernel::RandomStream& r, double a, double b) { return r.uniform(a, b); }, py::arg("a") = 0.0,
            py::arg("b") = 1.0);

    bindSnapshotView(m);

    py::class_<VehicleController, py::smart_holder>(m, "VehicleController")
        .def_property_readonly("id", &VehicleController::id)
        .def_property_readonly("type_id", &VehicleController::typeId)
        .def_property_readonly("road_id", &VehicleController::roadId)
        .def_property_readonly("lane_id", &VehicleController::laneId)
        .def_property_readonly("lane_index", &VehicleController::laneIndex)
        .def_property_readonly("speed", &VehicleController::speed)
        .def_property_readonly("max_speed", &VehicleController::maxSpeed)
        .def_property_readonly("speed_mode", &VehicleController::speedMode)
        .def("set_max_speed", &VehicleController::setMaxSpeed, py::arg("mps"))
        .def("set_speed", &VehicleController::setSpeed, py::arg("mps"))
        .def("slow_down", &VehicleController::slowDown, py::arg("mps"), py::arg("seconds"))
        .def("set_speed_mode", &VehicleController::setSpeedMode, py::arg("mode"))
        .def("change_lane", &VehicleController::changeLane, py::arg("lane_index"), py::arg("seconds"));

    py::class_<Condition, PythonCondition, py::smart_holder>(m, "Condition").def(py::init<>()).doc() =
        "Base of custom conditions: override test(self, vehicle) -> bool | set[str], or the "
        "vectorised test_all(self, snapshot) -> numpy bool array.";

    py::class_<TimeCondition, Condition, py::smart_holder>(m, "TimeCondition")
        .def(py::init([](const py::object& begin, const py::object& end) {
                 std::optional<SimTime> e;
                 if (!end.is_none()) e = toSimTime(end, "end");
                 return std::make_shared<TimeCondition>(toSimTime(begin, "begin"), e);
             }),
             py::arg("begin"), py::arg("end") = py::none());
    py::class_<SpeedConditionGreater, Condition, py::smart_holder>(m, "SpeedConditionGreater")
        .def(py::init(
                 [](const py::object& mps) { return std::make_shared<SpeedConditionGreater>(toNumber(mps, "speed")); }),
             py::arg("mps"));
    py::class_<SpeedConditionLess, Condition, py::smart_holder>(m, "SpeedConditionLess")
        .def(py::init(
                 [](const py::object& mps) { return std::make_shared<SpeedConditionLess>(toNumber(mps, "speed")); }),
             py::arg("mps"));
    py::class_<CarSetCondition, Condition, py::smart_holder>(m, "CarSetCondition")
        .def(py::init([](const py::object& ids) { return std::make_shared<CarSetCondition>(toIdSet(ids)); }),
             py::arg("ids"));
    py::class_<PolygonCondition, Condition, py::smart_holder>(m, "PolygonCondition")
        .def(py::init([](const py::iterable& points) {
                 std::vector<Eigen::Vector2d> vertices;
                 for (const py::handle p : points) vertices.push_back(toSumoPoint(p));
                 if (vertices.size() < 3) {
                     throw py::value_error("PolygonCondition needs 3 or more points, got " +
                                           std::to_string(vertices.size()));
                 }
                 return std::make_shared<PolygonCondition>(std::move(vertices));
             }),
             py::arg("points"));
    bindSpeedDifference<SpeedDifferenceConditionFaster>(
        py::class_<SpeedDifferenceConditionFaster, Condition, py::smart_holder>(m, "SpeedDifferenceConditionFaster"));
    bindSpeedDifference<SpeedDifferenceConditionSlower>(
        py::class_<SpeedDifferenceConditionSlower, Condition, py::smart_holder>(m, "SpeedDifferenceConditionSlower"));
    py::class_<TtcCondition, Condition, py::smart_holder>(m, "TtcCondition")
        .def(py::init([](const py::object& ttc, const py::object& distance) {
                 const double t = toNumber(ttc, "ttc");
                 const double d = toNumber(distance, "distance");
                 if (t <= 0) throw py::value_error("ttc must be > 0 s");
                 if (d < 0) throw py::value_error("distance must be >= 0 m");
                 return std::make_shared<TtcCondition>(t, d);
             }),
             py::arg("ttc"), py::arg("distance") = 100.0);
    py::class_<AndCondition, Condition, py::smart_holder>(m, "AndCondition")
        .def(py::init<ConditionPtr, ConditionPtr>(), py::arg("a"), py::arg("b"));
    py::class_<OrCondition, Condition, py::smart_holder>(m, "OrCondition")
        .def(py::init<ConditionPtr, ConditionPtr>(), py::arg("a"), py::arg("b"));
    py::class_<LimitCondition, Condition, py::smart_holder>(m, "LimitCondition")
        .def(py::init([](const py::object& n) {
                 if (!py::isinstance<py::int_>(n) || py::isinstance<py::bool_>(n)) {
                     throw py::type_error("LimitCondition needs a whole number of vehicles, got " +
                                          py::repr(n).cast<std::string>());
                 }
                 const long long count = n.cast<long long>();
                 if (count < 0)
                     throw py::value_error("LimitCondition needs a count >= 0, got " + std::to_string(count));
                 return std::make_shared<LimitCondition>(static_cast<unsigned>(count));
             }),
             py::arg("n"));
    py::class_<LikelihoodCondition, Condition, py::smart_holder>(m, "LikelihoodCondition")
        .def(py::init([](std::shared_ptr<kernel::RandomStream> rng, const py::object& p) {
                 if (!rng) throw py::type_error("LikelihoodCondition needs a random number generator");
                 return std::make_shared<LikelihoodCondition>(std::move(rng), toNumber(p, "likelihood"));
             }),
             py::arg("rng"), py::arg("p"));
    py::class_<DeferringCondition, Condition, py::smart_holder>(m, "DeferringCondition")
        .def(py::init([](std::shared_ptr<kernel::RandomStream> rng, const py::object& min, const py::object& max) {
                 if (!rng) throw py::type_error("DeferringCondition needs a random number generator");
                 const SimTime lo = toSimTime(min, "min");
                 const SimTime hi = toSimTime(max, "max");
                 if (lo < SimTime::zero() || hi < lo) throw py::value_error("DeferringCondition needs 0 <= min <= max");
                 return std::make_shared<DeferringCondition>(std::move(rng), lo, hi);
             }),
             py::arg("rng"), py::arg("min"), py::arg("max"));

    py::class_<Effect, PythonEffect, py::smart_holder>(m, "Effect").def(py::init<>()).doc() =
        "Base of custom effects: override apply(self, vehicle) and remove(self, vehicle); "
        "vehicle is a VehicleController.";
    py::class_<SpeedEffect, Effect, py::smart_holder>(m, "SpeedEffect")
        .def(py::init([](const py::object& mps) {
                 return std::make_shared<SpeedEffect>(toNumber(mps, "SpeedEffect speed"));
             }),
             py::arg("mps"))
        .def_property_readonly("speed", &SpeedEffect::speed);
    py::class_<StopEffect, Effect, py::smart_holder>(m, "StopEffect").def(py::init<>());
    py::class_<EmergencyStopEffect, Effect, py::smart_holder>(m, "EmergencyStopEffect").def(py::init<>());
    py::class_<SignalEffect, Effect, py::smart_holder>(m, "SignalEffect")
        .def(py::init<std::string>(), py::arg("cause"))
        .def_property_readonly("cause", &SignalEffect::cause);
    // Artery's older factory names.
    m.attr("SpeedEffectFactory") = m.attr("SpeedEffect");
    m.attr("StopEffectFactory") = m.attr("StopEffect");
    m.attr("SignalEffectFactory") = m.attr("SignalEffect");

    py::class_<Story, py::smart_holder>(m, "Story")
        .def(py::init([](ConditionPtr condition, const py::object& effects, std::optional<std::string> name) {
                 if (!condition) throw py::type_error("Story needs a condition, got None");
                 std::vector<EffectPtr> list;
                 if (!effects.is_none()) {
                     for (const py::handle e : py::iter(effects)) {
                         if (!py::isinstance<Effect>(e)) {
                             throw py::type_error("Story effects must be storyboard effects, got " +
                                                  py::repr(e).cast<std::string>());
                         }
                         list.push_back(e.cast<EffectPtr>());
                     }
                 }
                 return std::make_shared<Story>(std::move(condition), std::move(list), std::move(name));
             }),
             py::arg("condition"), py::arg("effects") = py::none(), py::arg("name") = py::none())
        .def_property_readonly("name", &Story::name)
        .def_property_readonly("activations", &Story::activations);

    const auto registerStory = [](const BoardHandle& h, StoryPtr story) {
        if (!story) throw py::type_error("registerStory needs a Story, got None");
        h.board().registerStory(std::move(story));
    };
    const auto randomGenerator = [](const BoardHandle& h, int k) {
        if (k < 0) throw py::value_error("the generator index must be >= 0");
        return h.board().randomStream(static_cast<unsigned>(k));
    };
    const auto convert = [](const BoardHandle&, double x, double y) {
        const Eigen::Vector2d c = ScriptContext::current().frame.toCanvas({x, y});
        return Coord{c.x(), c.y()};
    };
    py::class_<BoardHandle>(m, "Storyboard")
        .def("registerStory", registerStory, py::arg("story"))
        .def("register_story", registerStory, py::arg("story"))
        .def("getRandomNumberGenerator", randomGenerator, py::arg("k") = 0)
        .def("random_generator", randomGenerator, py::arg("k") = 0)
        .def("getWarmupEndTime", [](const BoardHandle&) { return SimTime::zero(); })
        .def_property_readonly("warmup_end_time", [](const BoardHandle&) { return SimTime::zero(); })
        .def("convertTraciPosition", convert, py::arg("x"), py::arg("y"))
        .def("convert_traci_position", convert, py::arg("x"), py::arg("y"))
        .def_property_readonly("stories", [](const BoardHandle& h) { return h.board().stories(); });
    m.def("_board", [] { return BoardHandle{}; });
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
