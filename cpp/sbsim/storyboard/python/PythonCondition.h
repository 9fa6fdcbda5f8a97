#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/trampoline_self_life_support.h>

#include <cstdint>
#include <memory>
#include <string>
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
    /// The class attribute `columns` (names such as "position", "speed"), if the script set one;
    /// otherwise every column, since a Python condition may read anything.
    traffic::SnapshotColumns columns() const override;
    ~PythonCondition() override;
    /// The script's class name (the Python object this trampoline belongs to).
    std::string typeName() const override {
        const pybind11::gil_scoped_acquire gil;
        const pybind11::object self =
            pybind11::cast(static_cast<const Condition*>(this), pybind11::return_value_policy::reference);
        return pybind11::str(self.get_type().attr("__name__"));
    }

private:
    std::vector<std::uint8_t> mask_;
    /// The views handed out this step; set false when the next step begins (or at destruction).
    std::shared_ptr<bool> stepValid_;
    bool vectorised_ = false;
};

}  // namespace sbsim::storyboard
