#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/trampoline_self_life_support.h>

#include <string>

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Trampoline for effects written in Python: apply(self, vehicle) and remove(self, vehicle), with
/// `vehicle` a VehicleController. They act directly, outside the built-in composition.
class PythonEffect : public Effect, public pybind11::trampoline_self_life_support {
public:
    void apply(EffectScope& scope) override { call("apply", scope); }
    void remove(EffectScope& scope) override { call("remove", scope); }
    /// The script's class name (the Python object this trampoline belongs to).
    std::string typeName() const override {
        const pybind11::gil_scoped_acquire gil;
        const pybind11::object self =
            pybind11::cast(static_cast<const Effect*>(this), pybind11::return_value_policy::reference);
        return pybind11::str(self.get_type().attr("__name__"));
    }

private:
    void call(const char* method, EffectScope& scope);
};

}  // namespace sbsim::storyboard
