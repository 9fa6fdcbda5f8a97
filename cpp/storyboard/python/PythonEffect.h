#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/trampoline_self_life_support.h>

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Trampoline for effects written in Python: apply(self, vehicle) and remove(self, vehicle), with
/// `vehicle` a VehicleController. They act directly, outside the built-in composition.
class PythonEffect : public Effect, public pybind11::trampoline_self_life_support {
public:
    void apply(EffectScope& scope) override { call("apply", scope); }
    void remove(EffectScope& scope) override { call("remove", scope); }

private:
    void call(const char* method, EffectScope& scope);
};

}  // namespace sbsim::storyboard
