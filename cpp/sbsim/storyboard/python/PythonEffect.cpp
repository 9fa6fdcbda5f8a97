#include "sbsim/storyboard/python/PythonEffect.h"

#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/python/ScriptContext.h"

namespace py = pybind11;

namespace sbsim::storyboard {

void PythonEffect::call(const char* method, EffectScope& scope) {
    const std::string where =
        std::string("in ") +
        py::str(py::type::of(py::cast(static_cast<const Effect*>(this))).attr("__name__")).cast<std::string>() + "." +
        method + " (story " + scope.story().name() + ", vehicle " + scope.vehicleId() + ")";
    try {
        const py::function f = py::get_override(static_cast<const Effect*>(this), method);
        if (!f) {
            const py::handle self = py::cast(static_cast<const Effect*>(this));
            throwContractError(self, py::str(py::type::of(self).attr("__name__")).cast<std::string>() +
                                         " must define " + method + "(self, vehicle)");
        }
        f(py::cast(scope.handle()));
    } catch (py::error_already_set& e) {
        throwStoryError(e, where);
    }
}

}  // namespace sbsim::storyboard
