#include <pybind11/stl.h>

#include <map>
#include <string>
#include <variant>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/storyboard/ScenarioMachine.h"
#include "sbsim/storyboard/ScenarioParameters.h"
#include "sbsim/storyboard/conditions/ParameterCondition.h"
#include "sbsim/storyboard/effects/ParameterEffect.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/Bindings.h"
#include "sbsim/storyboard/python/ScriptContext.h"

namespace py = pybind11;

namespace sbsim::storyboard {

namespace {

using M = ScenarioMachine;

template <typename T>
T named(const std::map<std::string, T>& table, const std::string& name, const char* what) {
    const auto it = table.find(name);
    if (it == table.end()) {
        std::string known;
        for (const auto& [k, v] : table) known += (known.empty() ? "" : ", ") + k;
        throw py::value_error(std::string(what) + " must be one of " + known + ", got '" + name + "'");
    }
    return it->second;
}

const std::map<std::string, M::Kind> kinds{
    {"storyboard", M::Kind::storyboard},        {"story", M::Kind::story},       {"act", M::Kind::act},
    {"maneuver_group", M::Kind::maneuverGroup}, {"maneuver", M::Kind::maneuver}, {"event", M::Kind::event}};
const std::map<std::string, M::Edge> edges{{"none", M::Edge::none},
                                           {"rising", M::Edge::rising},
                                           {"falling", M::Edge::falling},
                                           {"risingOrFalling", M::Edge::risingOrFalling}};
const std::map<std::string, M::Priority> priorities{
    {"parallel", M::Priority::parallel}, {"overwrite", M::Priority::overwrite}, {"skip", M::Priority::skip}};

/// [[(name, condition, edge, delay), ...], ...]: OR of AND groups.
M::Trigger toTrigger(const py::handle& groups, const char* what) {
    M::Trigger trigger;
    if (groups.is_none()) return trigger;
    for (const py::handle group : py::iter(groups)) {
        auto& out = trigger.emplace_back();
        for (const py::handle item : py::iter(group)) {
            const py::tuple t = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
            if (t.size() != 4)
                throw py::type_error(std::string(what) + ": each condition is (name, condition, edge, delay)");
            if (!py::isinstance<Condition>(t[1])) {
                throw py::type_error(std::string(what) + ": '" + py::str(t[0]).cast<std::string>() +
                                     "' is not a storyboard condition");
            }
            out.push_back({t[0].cast<std::string>(), t[1].cast<ConditionPtr>(),
                           named(edges, t[2].cast<std::string>(), "conditionEdge"), toNumber(t[3], "delay")});
        }
    }
    return trigger;
}

/// A parameter value from Python: bool, int or float as a number (true: 1), str as a text.
ScenarioParameters::Value toValue(const py::handle& v, const char* what) {
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? 1.0 : 0.0;
    return toNumber(v, what);
}

const std::map<std::string, ScenarioParameters::Rule> rules{
    {"greaterThan", ScenarioParameters::Rule::greaterThan},
    {"lessThan", ScenarioParameters::Rule::lessThan},
    {"equalTo", ScenarioParameters::Rule::equalTo},
    {"greaterOrEqual", ScenarioParameters::Rule::greaterOrEqual},
    {"lessOrEqual", ScenarioParameters::Rule::lessOrEqual},
    {"notEqualTo", ScenarioParameters::Rule::notEqualTo}};
const std::map<std::string, ParameterEffect::Op> ops{
    {"set", ParameterEffect::Op::set}, {"add", ParameterEffect::Op::add}, {"multiply", ParameterEffect::Op::multiply}};

py::object toPython(const ScenarioParameters::Value& v) {
    if (const double* d = std::get_if<double>(&v)) return py::float_(*d);
    return py::str(std::get<std::string>(v));
}

}  // namespace

void bindScenario(py::module_& m) {
    py::class_<ScenarioParameters, py::smart_holder>(m, "ScenarioParameters",
                                                     "an OpenSCENARIO storyboard's global parameters while it runs")
        .def(py::init<>())
        .def(
            "declare",
            [](ScenarioParameters& self, const std::string& name, const py::object& value) {
                self.declare(name, toValue(value, "ScenarioParameters value"));
            },
            py::arg("name"), py::arg("value"))
        .def("__contains__", &ScenarioParameters::has)
        .def(
            "get", [](const ScenarioParameters& self, const std::string& name) { return toPython(self.get(name)); },
            py::arg("name"));
    py::class_<ParameterCondition, Condition, py::smart_holder>(m, "ParameterCondition")
        .def(py::init([](std::shared_ptr<ScenarioParameters> parameters, const std::string& name,
                         const std::string& rule, const py::object& value) {
                 return std::make_shared<ParameterCondition>(std::move(parameters), name,
                                                             named(rules, rule, "ParameterCondition rule"),
                                                             toValue(value, "ParameterCondition value"));
             }),
             py::arg("parameters"), py::arg("name"), py::arg("rule"), py::arg("value"));
    py::class_<ParameterEffect, WorldEffect, py::smart_holder>(m, "ParameterEffect")
        .def(py::init([](std::shared_ptr<ScenarioParameters> parameters, const std::string& name, const std::string& op,
                         const py::object& value) {
                 return std::make_shared<ParameterEffect>(std::move(parameters), name,
                                                          named(ops, op, "ParameterEffect op"),
                                                          toValue(value, "ParameterEffect value"));
             }),
             py::arg("parameters"), py::arg("name"), py::arg("op"), py::arg("value"));
    py::class_<M, py::smart_holder>(
        m, "ScenarioMachine", "OpenSCENARIO's storyboard state machine; ElementCondition stories show its elements")
        .def(py::init([] {
            auto machine = std::make_shared<M>();
            // The storyboard's stop trigger ends the run (after the step it fired in).
            if (Storyboard* board = ScriptContext::current().board; board != nullptr) {
                machine->onEnd([board] { board->simulation().stop(); });
            }
            return machine;
        }))
        .def(
            "add",
            [](M& self, const std::string& name, const std::string& kind, std::optional<std::size_t> parent,
               const py::object& start, const py::object& stop, std::uint64_t maxExecutions,
               const std::string& priority, bool selectTriggeringEntities) {
                return self.add({name, named(kinds, kind, "kind"), parent, toTrigger(start, "start trigger"),
                                 toTrigger(stop, "stop trigger"), maxExecutions,
                                 named(priorities, priority, "priority"), selectTriggeringEntities});
            },
            py::arg("name"), py::arg("kind"), py::arg("parent") = py::none(), py::arg("start") = py::none(),
            py::arg("stop") = py::none(), py::arg("max_executions") = 1, py::arg("priority") = "parallel",
            py::arg("select_triggering_entities") = false)
        .def(
            "add_action",
            [](M& self, std::size_t event, std::shared_ptr<Effect> action) {
                if (event >= self.size()) throw py::index_error("no storyboard element " + std::to_string(event));
                self.addAction(event, std::move(action));
            },
            py::arg("event"), py::arg("action"))
        .def("__len__", &M::size)
        .def("state", [](const M& self, std::size_t e) { return std::string(M::stateName(self.state(e))); })
        .def("executions", &M::executions)
        .def("triggering_entities", &M::triggeringEntities)
        .def_property_readonly("ended", &M::ended);
}

}  // namespace sbsim::storyboard
