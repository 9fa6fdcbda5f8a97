#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/trampoline_self_life_support.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// Trampoline for conditions written in Python: test(self, vehicle) -> bool | set of ids, or the
/// vectorised test_all(self, snapshot) -> numpy bool mask, called once per step.
class PythonCondition : public Condition, public pybind11::trampoline_self_life_support {
public:
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    void forget(std::string_view vehicleId) override;
    ~PythonCondition() override;

private:
    std::vector<std::uint8_t> mask_;
    /// The views handed out this step; set false when the next step begins (or at destruction).
    std::shared_ptr<bool> stepValid_;
    bool vectorised_ = false;
};

}  // namespace sbsim::storyboard
