#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include <limits>
#include <map>
#include <utility>

#include "sbsim/storyboard/conditions/AccelerationCondition.h"
#include "sbsim/storyboard/conditions/AllCondition.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/AnyCondition.h"
#include "sbsim/storyboard/conditions/CamCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/CollisionCondition.h"
#include "sbsim/storyboard/conditions/DeferringCondition.h"
#include "sbsim/storyboard/conditions/DenmCondition.h"
#include "sbsim/storyboard/conditions/DistanceCondition.h"
#include "sbsim/storyboard/conditions/ElementCondition.h"
#include "sbsim/storyboard/conditions/ElementStateCondition.h"
#include "sbsim/storyboard/conditions/EntityCondition.h"
#include "sbsim/storyboard/conditions/EquippedCondition.h"
#include "sbsim/storyboard/conditions/HeadwayCondition.h"
#include "sbsim/storyboard/conditions/HoldCondition.h"
#include "sbsim/storyboard/conditions/LaneCondition.h"
#include "sbsim/storyboard/conditions/LatchCondition.h"
#include "sbsim/storyboard/conditions/LikelihoodCondition.h"
#include "sbsim/storyboard/conditions/LimitCondition.h"
#include "sbsim/storyboard/conditions/NotCondition.h"
#include "sbsim/storyboard/conditions/OrCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"
#include "sbsim/storyboard/conditions/PositionDistanceCondition.h"
#include "sbsim/storyboard/conditions/RelativeDistanceCondition.h"
#include "sbsim/storyboard/conditions/RisingCondition.h"
#include "sbsim/storyboard/conditions/RoadCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/SpeedDifferenceCondition.h"
#include "sbsim/storyboard/conditions/StandstillCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/conditions/TrafficSignalCondition.h"
#include "sbsim/storyboard/conditions/TraveledDistanceCondition.h"
#include "sbsim/storyboard/conditions/TriggeringEntitiesCondition.h"
#include "sbsim/storyboard/conditions/TtcCondition.h"
#include "sbsim/storyboard/conditions/TypeCondition.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/PythonCondition.h"

namespace py = pybind11;

namespace sbsim::storyboard {

using kernel::SimTime;

namespace {

template <typename Condition, typename Class>
void bindSpeedDifference(Class&& cls) {
    cls.def(py::init([](const py::object& delta, const py::object& distance) {
                return std::make_shared<Condition>(toNumber(delta, "delta"), optionalDistance(distance));
            }),
            py::arg("delta"), py::arg("distance") = py::none());
}

/// The operands of an n-ary condition: each a storyboard condition, at least one.
std::vector<ConditionPtr> operands(const py::args& args, const char* what) {
    if (args.empty()) throw py::type_error(std::string(what) + " needs at least one condition");
    std::vector<ConditionPtr> list;
    for (const py::handle a : args) {
        if (!py::isinstance<Condition>(a)) {
            throw py::type_error(std::string(what) + " operands must be storyboard conditions, got " +
                                 py::repr(a).cast<std::string>());
        }
        list.push_back(a.cast<ConditionPtr>());
    }
    return list;
}

/// One id or an iterable of ids, each a string; `what` names them in the error.
std::set<std::string> toStringSet(const py::handle& ids, const std::string& what) {
    if (py::isinstance<py::str>(ids)) return {ids.cast<std::string>()};
    if (!py::isinstance<py::iterable>(ids))
        throw py::type_error(what + " must be a string or an iterable of strings, got " +
                             py::repr(ids).cast<std::string>());
    std::set<std::string> out;
    for (const py::handle id : py::iter(ids)) {
        if (!py::isinstance<py::str>(id))
            throw py::type_error(what + " must be strings, got " + py::repr(id).cast<std::string>());
        out.insert(id.cast<std::string>());
    }
    return out;
}

/// A distance condition's rule and kind by name (`what`: the condition, for the error).
std::pair<ComparisonRule, geometry::DistanceKind> ruleAndKind(const std::string& rule, const std::string& kind,
                                                              const std::string& what) {
    const auto r = ruleNamed(rule);
    if (!r) {
        throw py::value_error(what +
                              " rule must be 'lessThan', 'lessOrEqual', 'equalTo', 'greaterOrEqual', 'greaterThan' "
                              "or 'notEqualTo', got '" +
                              rule + "'");
    }
    const auto k = RelativeDistanceCondition::kindNamed(kind);
    if (!k) throw py::value_error(what + " kind must be 'longitudinal', 'lateral' or 'cartesian', got '" + kind + "'");
    return {*r, *k};
}

}  // namespace

void bindConditions(py::module_& m) {
    py::class_<Condition, PythonCondition, py::smart_holder>(m, "Condition")
        .def(py::init<>())
        // A subclass's own `columns` (a class attribute) shadows this, and PythonCondition reads it.
        .def_property_readonly(
            "columns", [](const Condition& c) { return py::tuple(py::cast(c.columns().names())); },
            "The snapshot columns this condition reads (its children declare their own).")
        .doc() =
        "Base of custom conditions: override test(self, vehicle) -> bool | set[str], or the "
        "vectorised test_all(self, snapshot) -> numpy bool array; name the snapshot columns read "
        "in a class attribute `columns` (default: all).";

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
                 bool canvas = false;
                 for (const py::handle p : points) {
                     canvas = canvas || py::isinstance<Coord>(p);
                     vertices.push_back(toSumoPoint(p));
                 }
                 if (vertices.size() < 3) {
                     throw py::value_error("PolygonCondition needs 3 or more points, got " +
                                           std::to_string(vertices.size()));
                 }
                 auto polygon = std::make_shared<PolygonCondition>(std::move(vertices));
                 if (canvas) polygon->setGivenFrame(PolygonCondition::GivenFrame::Canvas);
                 return polygon;
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
    py::class_<DistanceCondition, Condition, py::smart_holder>(m, "DistanceCondition")
        .def(py::init([](const py::object& target, const py::object& distance) {
                 const double d = toNumber(distance, "DistanceCondition distance");
                 if (d < 0) throw py::value_error("DistanceCondition distance must be >= 0 m");
                 if (py::isinstance<py::str>(target)) {
                     auto id = target.cast<std::string>();
                     if (id.empty()) throw py::value_error("DistanceCondition target vehicle id is empty");
                     return std::make_shared<DistanceCondition>(std::move(id), d);
                 }
                 if (!py::isinstance<Coord>(target) && !(py::isinstance<py::tuple>(target) && py::len(target) == 2)) {
                     throw py::type_error(
                         "DistanceCondition target must be a storyboard.Coord, an (x, y) tuple or a vehicle id, got " +
                         py::repr(target).cast<std::string>());
                 }
                 return std::make_shared<DistanceCondition>(toSumoPoint(target), d);
             }),
             py::arg("target"), py::arg("distance"));
    py::class_<StandstillCondition, Condition, py::smart_holder>(m, "StandstillCondition")
        .def(py::init([](const py::object& seconds) {
                 const SimTime duration = toSimTime(seconds, "StandstillCondition seconds");
                 if (duration < SimTime::zero()) throw py::value_error("StandstillCondition needs seconds >= 0");
                 return std::make_shared<StandstillCondition>(duration);
             }),
             py::arg("seconds"));
    py::class_<AccelerationConditionGreater, Condition, py::smart_holder>(m, "AccelerationConditionGreater")
        .def(py::init([](const py::object& a) {
                 return std::make_shared<AccelerationConditionGreater>(toNumber(a, "acceleration"));
             }),
             py::arg("a"));
    py::class_<AccelerationConditionLess, Condition, py::smart_holder>(m, "AccelerationConditionLess")
        .def(py::init([](const py::object& a) {
                 return std::make_shared<AccelerationConditionLess>(toNumber(a, "acceleration"));
             }),
             py::arg("a"));
    py::class_<RoadCondition, Condition, py::smart_holder>(m, "RoadCondition")
        .def(py::init([](const py::object& ids) {
                 return std::make_shared<RoadCondition>(toStringSet(ids, "RoadCondition road ids"));
             }),
             py::arg("ids"));
    py::class_<LaneCondition, Condition, py::smart_holder>(m, "LaneCondition")
        .def(py::init([](const py::object& ids) {
                 return std::make_shared<LaneCondition>(toStringSet(ids, "LaneCondition lane ids"));
             }),
             py::arg("ids"));
    py::class_<TypeCondition, Condition, py::smart_holder>(m, "TypeCondition")
        .def(py::init([](const std::string& pattern) { return std::make_shared<TypeCondition>(pattern); }),
             py::arg("pattern"));
    py::class_<HeadwayCondition, Condition, py::smart_holder>(m, "HeadwayCondition")
        .def(py::init([](const py::object& seconds) {
                 const double s = toNumber(seconds, "HeadwayCondition seconds");
                 if (s <= 0) throw py::value_error("HeadwayCondition needs seconds > 0");
                 return std::make_shared<HeadwayCondition>(s);
             }),
             py::arg("seconds"));
    py::class_<CollisionCondition, Condition, py::smart_holder>(m, "CollisionCondition").def(py::init<>());
    py::class_<TrafficSignalCondition, Condition, py::smart_holder>(m, "TrafficSignalCondition")
        .def(py::init<std::string, std::string, std::vector<int>>(), py::arg("tls_id"), py::arg("state"),
             py::arg("links") = std::vector<int>{})
        .def_property_readonly("tls_id", &TrafficSignalCondition::tls)
        .def_property_readonly("state", &TrafficSignalCondition::state)
        .def_property_readonly("links", &TrafficSignalCondition::links);
    py::class_<TraveledDistanceCondition, Condition, py::smart_holder>(m, "TraveledDistanceCondition")
        .def(py::init([](const py::object& distance) {
                 const double d = toNumber(distance, "TraveledDistanceCondition distance");
                 if (d < 0) throw py::value_error("TraveledDistanceCondition distance must be >= 0 m");
                 return std::make_shared<TraveledDistanceCondition>(d);
             }),
             py::arg("distance"))
        .def_property_readonly("distance", &TraveledDistanceCondition::distance);
    py::class_<RelativeDistanceCondition, Condition, py::smart_holder>(m, "RelativeDistanceCondition")
        .def(py::init([](const std::string& vehicle, const py::object& value, const std::string& rule,
                         const std::string& kind, bool freespace) {
                 if (vehicle.empty()) throw py::value_error("RelativeDistanceCondition vehicle id is empty");
                 const double d = toNumber(value, "RelativeDistanceCondition value");
                 if (d < 0) throw py::value_error("RelativeDistanceCondition value must be >= 0 m");
                 const auto [r, k] = ruleAndKind(rule, kind, "RelativeDistanceCondition");
                 return std::make_shared<RelativeDistanceCondition>(vehicle, d, r, k, freespace);
             }),
             py::arg("vehicle"), py::arg("value"), py::arg("rule") = "lessThan", py::arg("kind") = "cartesian",
             py::arg("freespace") = false)
        .def_property_readonly("vehicle", &RelativeDistanceCondition::vehicle)
        .def_property_readonly("value", &RelativeDistanceCondition::value)
        .def_property_readonly("rule",
                               [](const RelativeDistanceCondition& c) { return std::string(ruleName(c.rule())); })
        .def_property_readonly("kind",
                               [](const RelativeDistanceCondition& c) {
                                   return std::string(RelativeDistanceCondition::kindName(c.kind()));
                               })
        .def_property_readonly("freespace", &RelativeDistanceCondition::freespace);
    py::class_<PositionDistanceCondition, Condition, py::smart_holder>(m, "PositionDistanceCondition")
        .def(py::init([](const py::object& point, const py::object& value, const std::string& rule,
                         const std::string& kind, bool freespace) {
                 const double d = toNumber(value, "PositionDistanceCondition value");
                 if (d < 0) throw py::value_error("PositionDistanceCondition value must be >= 0 m");
                 const auto [r, k] = ruleAndKind(rule, kind, "PositionDistanceCondition");
                 return std::make_shared<PositionDistanceCondition>(toSumoPoint(point), d, r, k, freespace);
             }),
             py::arg("point"), py::arg("value"), py::arg("rule") = "lessThan", py::arg("kind") = "cartesian",
             py::arg("freespace") = false)
        .def_property_readonly("value", &PositionDistanceCondition::value)
        .def_property_readonly("freespace", &PositionDistanceCondition::freespace);
    py::class_<AndCondition, Condition, py::smart_holder>(m, "AndCondition")
        .def(py::init<ConditionPtr, ConditionPtr>(), py::arg("a"), py::arg("b"));
    py::class_<OrCondition, Condition, py::smart_holder>(m, "OrCondition")
        .def(py::init<ConditionPtr, ConditionPtr>(), py::arg("a"), py::arg("b"));
    py::class_<NotCondition, Condition, py::smart_holder>(m, "NotCondition")
        .def(py::init<ConditionPtr>(), py::arg("condition"));
    py::class_<AllCondition, Condition, py::smart_holder>(m, "AllCondition").def(py::init([](const py::args& args) {
        return std::make_shared<AllCondition>(operands(args, "AllCondition"));
    }));
    py::class_<AnyCondition, Condition, py::smart_holder>(m, "AnyCondition").def(py::init([](const py::args& args) {
        return std::make_shared<AnyCondition>(operands(args, "AnyCondition"));
    }));
    // V2X: what a vehicle heard (the evaluation context's stations).
    py::class_<DenmCondition, Condition, py::smart_holder>(m, "DenmCondition")
        .def(py::init([](const py::object& cause, const py::object& maxAge, const py::object& within,
                         const py::object& ahead, const py::object& inRelevanceArea) {
                 std::optional<int> c;
                 if (!cause.is_none()) {
                     if (!py::isinstance<py::int_>(cause) || py::isinstance<py::bool_>(cause))
                         throw py::type_error("DenmCondition cause must be a whole number (a cause code), got " +
                                              py::repr(cause).cast<std::string>());
                     const long long code = cause.cast<long long>();
                     if (code < 0 || code > 255)
                         throw py::value_error("DenmCondition cause must be a cause code 0 to 255, got " +
                                               std::to_string(code));
                     c = static_cast<int>(code);
                 }
                 std::optional<SimTime> age;
                 if (!maxAge.is_none()) {
                     age = toSimTime(maxAge, "DenmCondition max_age");
                     if (*age < SimTime::zero()) throw py::value_error("DenmCondition needs max_age >= 0");
                 }
                 DenmRelevance relevance;
                 relevance.within = optionalDistance(within);
                 const auto flag = [](const py::object& value, const char* name) {
                     if (!py::isinstance<py::bool_>(value))
                         throw py::type_error(std::string("DenmCondition ") + name + " must be True or False, got " +
                                              py::repr(value).cast<std::string>());
                     return value.cast<bool>();
                 };
                 relevance.ahead = flag(ahead, "ahead");
                 relevance.inRelevanceArea = flag(inRelevanceArea, "in_relevance_area");
                 return std::make_shared<DenmCondition>(c, age, relevance);
             }),
             py::arg("cause") = py::none(), py::arg("max_age") = py::none(), py::arg("within") = py::none(),
             py::arg("ahead") = false, py::arg("in_relevance_area") = false)
        .def("describe", &DenmCondition::describe);
    py::class_<CamCondition, Condition, py::smart_holder>(m, "CamCondition")
        .def(py::init([](const py::object& distance, const py::object& maxAge) {
                 std::optional<SimTime> age;
                 if (!maxAge.is_none()) {
                     age = toSimTime(maxAge, "CamCondition max_age");
                     if (*age < SimTime::zero()) throw py::value_error("CamCondition needs max_age >= 0");
                 }
                 return std::make_shared<CamCondition>(optionalDistance(distance), age);
             }),
             py::arg("distance") = py::none(), py::arg("max_age") = py::none())
        .def("describe", &CamCondition::describe);
    py::class_<EquippedCondition, Condition, py::smart_holder>(m, "EquippedCondition").def(py::init<>());
    py::class_<HoldCondition, Condition, py::smart_holder>(m, "HoldCondition")
        .def(py::init([](ConditionPtr condition, const py::object& seconds) {
                 const SimTime duration = toSimTime(seconds, "HoldCondition seconds");
                 if (duration < SimTime::zero()) throw py::value_error("HoldCondition needs seconds >= 0");
                 return std::make_shared<HoldCondition>(std::move(condition), duration);
             }),
             py::arg("condition"), py::arg("seconds"));
    py::class_<RisingCondition, Condition, py::smart_holder>(m, "RisingCondition")
        .def(py::init<ConditionPtr>(), py::arg("condition"));
    py::class_<LatchCondition, Condition, py::smart_holder>(m, "LatchCondition")
        .def(py::init<ConditionPtr>(), py::arg("condition"));
    py::class_<EntityCondition, Condition, py::smart_holder>(m, "EntityCondition")
        .def(py::init<std::string, ConditionPtr>(), py::arg("vehicle"), py::arg("condition"));
    py::class_<TriggeringEntitiesCondition, Condition, py::smart_holder>(m, "TriggeringEntitiesCondition")
        .def(py::init([](std::vector<std::shared_ptr<EntityCondition>> entities, const std::string& rule) {
                 if (rule != "any" && rule != "all")
                     throw py::value_error("TriggeringEntitiesCondition rule must be 'any' or 'all', got '" + rule +
                                           "'");
                 if (entities.empty()) throw py::value_error("TriggeringEntitiesCondition needs at least one entity");
                 return std::make_shared<TriggeringEntitiesCondition>(std::move(entities), rule == "all");
             }),
             py::arg("entities"), py::arg("rule") = "any");
    py::class_<ElementCondition, Condition, py::smart_holder>(m, "ElementCondition")
        .def(py::init([](std::shared_ptr<ScenarioMachine> machine, std::size_t element, const py::object& actors) {
                 std::set<std::string> ids;
                 if (!actors.is_none()) ids = toStringSet(actors, "ElementCondition actors");
                 return std::make_shared<ElementCondition>(std::move(machine), element, std::move(ids));
             }),
             py::arg("machine"), py::arg("element"), py::arg("actors") = py::none());
    py::class_<ElementStateCondition, Condition, py::smart_holder>(m, "ElementStateCondition")
        .def(py::init([](std::shared_ptr<ScenarioMachine> machine, std::size_t element, const std::string& what) {
                 using M = ScenarioMachine;
                 static const std::map<std::string, M::State> states{{"standbyState", M::State::standby},
                                                                     {"runningState", M::State::running},
                                                                     {"completeState", M::State::complete}};
                 static const std::map<std::string, M::Transition> transitions{
                     {"startTransition", M::Transition::start},
                     {"endTransition", M::Transition::end},
                     {"stopTransition", M::Transition::stop},
                     {"skipTransition", M::Transition::skip}};
                 if (const auto s = states.find(what); s != states.end())
                     return std::make_shared<ElementStateCondition>(std::move(machine), element, s->second,
                                                                    std::nullopt);
                 if (const auto t = transitions.find(what); t != transitions.end())
                     return std::make_shared<ElementStateCondition>(std::move(machine), element, std::nullopt,
                                                                    t->second);
                 throw py::value_error("ElementStateCondition: unknown state or transition '" + what + "'");
             }),
             py::arg("machine"), py::arg("element"), py::arg("state"));
    py::class_<LimitCondition, Condition, py::smart_holder>(m, "LimitCondition")
        .def(py::init([](const py::object& n) {
                 if (!py::isinstance<py::int_>(n) || py::isinstance<py::bool_>(n)) {
                     throw py::type_error("LimitCondition needs a whole number of vehicles, got " +
                                          py::repr(n).cast<std::string>());
                 }
                 // Compared as Python ints: a count beyond 64 bits must not wrap into a small one.
                 if (n < py::int_(0) || n > py::int_(std::numeric_limits<std::int64_t>::max())) {
                     throw py::value_error("LimitCondition needs a count from 0 to 2**63-1, got " +
                                           py::repr(n).cast<std::string>());
                 }
                 return std::make_shared<LimitCondition>(n.cast<std::int64_t>());
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
}

}  // namespace sbsim::storyboard
