#include "sbsim/storyboard/python/PythonCondition.h"

#include <pybind11/numpy.h>

#include <fmt/format.h>

#include <algorithm>

#include "sbsim/python/SnapshotView.h"
#include "sbsim/storyboard/python/ScriptContext.h"

namespace py = pybind11;

namespace sbsim::storyboard {

namespace {
std::string className(const Condition* self) {
    return py::str(py::type::of(py::cast(self)).attr("__name__")).cast<std::string>();
}
}  // namespace

traffic::SnapshotColumns PythonCondition::columns() const {
    const py::gil_scoped_acquire gil;
    const py::object self = py::cast(static_cast<const Condition*>(this));
    // Only a `columns` the script's classes define; the bound base's property would ask back here.
    py::object declared;
    for (const py::handle cls : py::type::of(self).attr("__mro__")) {
        if (cls.attr("__module__").cast<std::string>() == "_sbsim") break;
        if (const py::dict own = cls.attr("__dict__"); own.contains("columns")) {
            declared = own["columns"];
            break;
        }
    }
    if (!declared) return traffic::SnapshotColumns::all();
    const auto wrong = [&] {
        throwContractError(self, className(this) + ".columns must be a sequence of column names (" +
                                     traffic::SnapshotColumns::all().str() + "), got " +
                                     py::repr(declared).cast<std::string>());
    };
    if (py::isinstance<py::str>(declared) || !py::hasattr(declared, "__iter__")) wrong();
    traffic::SnapshotColumns columns;
    for (const py::handle name : declared) {
        if (!py::isinstance<py::str>(name)) wrong();
        const auto column = traffic::SnapshotColumns::named(name.cast<std::string>());
        if (!column) wrong();
        columns |= *column;
    }
    return columns;
}

PythonCondition::~PythonCondition() {
    if (stepValid_) *stepValid_ = false;
}

void PythonCondition::prepare(const EvaluationContext& ctx) {
    // A new step: views handed out before may no longer be read.
    if (stepValid_) *stepValid_ = false;
    stepValid_ = std::make_shared<bool>(true);
    try {
        const py::function testAll = py::get_override(static_cast<const Condition*>(this), "test_all");
        vectorised_ = static_cast<bool>(testAll);
        if (!vectorised_) return;
        const py::object result = testAll(python::SnapshotView{&ctx.snapshot(), stepValid_, py::dict()});
        const auto mask = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(result);
        PyErr_Clear();  // ensure() leaves a conversion error behind for None and the like
        if (!mask || mask.ndim() != 1 || mask.shape(0) != ctx.snapshot().size()) {
            throwContractError(py::cast(static_cast<const Condition*>(this)),
                               fmt::format("{}.test_all must return one boolean per vehicle ({} this step)",
                                           className(this), ctx.snapshot().size()));
        }
        mask_.assign(mask.data(), mask.data() + mask.shape(0));
    } catch (py::error_already_set& e) {
        throwStoryError(e, "in " + className(this) + ".test_all");
    }
}

ConditionResult PythonCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    if (vectorised_) return mask_[ego] != 0;
    try {
        const py::function test = py::get_override(static_cast<const Condition*>(this), "test");
        const py::handle self = py::cast(static_cast<const Condition*>(this));
        if (!test)
            throwContractError(self, className(this) + " must define test(self, vehicle) or test_all(self, snapshot)");
        const py::object result = test(python::VehicleView{&ctx.snapshot(), ego, stepValid_});
        if (py::isinstance<py::bool_>(result)) return result.cast<bool>();
        if (py::str(py::type::of(result).attr("__name__")).cast<std::string>() == "bool_") {
            return py::bool_(result).cast<bool>();  // numpy's bool
        }
        const auto wrongResult = [&] {
            throwContractError(self, className(this) + ".test must return a bool or a set of vehicle ids, got " +
                                         py::repr(result).cast<std::string>());
        };
        if (py::isinstance<py::str>(result) || !py::hasattr(result, "__iter__")) wrongResult();
        std::vector<VehicleIndex> others;
        for (const py::handle id : result) {
            if (!py::isinstance<py::str>(id)) wrongResult();
            if (const auto i = ctx.snapshot().indexOf(id.cast<std::string>()); i && *i != ego) others.push_back(*i);
        }
        std::sort(others.begin(), others.end());
        others.erase(std::unique(others.begin(), others.end()), others.end());
        return ConditionResult::ofOthers(std::move(others));
    } catch (py::error_already_set& e) {
        throwStoryError(e, "in " + className(this) + ".test for vehicle " + ctx.snapshot().ids()[ego]);
    }
}

void PythonCondition::forget(std::string_view vehicleId) {
    try {
        if (const py::function f = py::get_override(static_cast<const Condition*>(this), "forget"))
            f(std::string(vehicleId));
    } catch (py::error_already_set& e) {
        throwStoryError(e, "in " + className(this) + ".forget");
    }
}

}  // namespace sbsim::storyboard
