#include "sbsim/storyboard/python/PythonCriterion.h"

#include <pybind11/stl.h>

#include <string_view>

#include "sbsim/storyboard/python/ScriptContext.h"

namespace py = pybind11;

namespace sbsim::storyboard {

namespace {

/// What evaluate(run) reads, as plain Python values.
py::object runRecord(const CriterionRun& run) {
    const py::module_ json = py::module_::import("json");
    py::list events;
    std::string_view lines = run.events;
    while (!lines.empty()) {
        const std::size_t end = lines.find('\n');
        const std::string_view line = lines.substr(0, end);
        if (!line.empty()) events.append(json.attr("loads")(py::str(line.data(), line.size())));
        lines = end == std::string_view::npos ? std::string_view{} : lines.substr(end + 1);
    }
    py::dict statistics;
    if (run.statistics != nullptr) {
        for (const auto& [name, a] : run.statistics->aggregates()) {
            py::dict d;
            d["count"] = a.count;
            d["sum"] = a.sum;
            d["mean"] = a.mean();
            d["min"] = a.min;
            d["max"] = a.max;
            statistics[py::str(name)] = d;
        }
    }
    py::dict activations;
    for (const StoryPtr& s : run.stories) activations[py::str(s->name())] = s->counters().activations();
    const py::object record = py::module_::import("types").attr("SimpleNamespace")();
    record.attr("events") = events;
    record.attr("statistics") = statistics;
    record.attr("activations") = activations;
    return record;
}

}  // namespace

std::string PythonCriterion::describe() const {
    const py::gil_scoped_acquire gil;
    const py::object self = py::cast(static_cast<const Criterion*>(this), py::return_value_policy::reference);
    return py::str(py::type::of(self).attr("__name__")).cast<std::string>() + "()";
}

CriterionVerdict PythonCriterion::verdict(const CriterionRun& run) const {
    const py::gil_scoped_acquire gil;
    const py::handle self = py::cast(static_cast<const Criterion*>(this));
    const std::string where = "in " + name() + ".evaluate";
    try {
        const py::function f = py::get_override(static_cast<const Criterion*>(this), "evaluate");
        if (!f) throwContractError(self, name() + " must define evaluate(self, run)");
        const py::object result = f(runRecord(run));
        if (py::isinstance<py::bool_>(result)) {
            const bool passed = result.cast<bool>();
            return {passed, passed ? "passed" : "failed", "passed"};
        }
        if (py::isinstance<py::tuple>(result) && py::len(result) == 3 &&
            py::isinstance<py::bool_>(result[py::int_(0)])) {
            const py::tuple t = result.cast<py::tuple>();
            return {t[0].cast<bool>(), py::str(t[1]).cast<std::string>(), py::str(t[2]).cast<std::string>()};
        }
        throwContractError(self, name() + ".evaluate must return a bool or (passed, actual, expected), got " +
                                     py::repr(result).cast<std::string>());
    } catch (py::error_already_set& e) {
        throwStoryError(e, where);
    }
}

}  // namespace sbsim::storyboard
