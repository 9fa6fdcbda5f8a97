#pragma once

#include <memory>
#include <string>

#include "sbsim/storyboard/ScenarioParameters.h"
#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// Once, at activation: a storyboard parameter is set to a value (OpenSCENARIO's
/// ParameterSetAction), or has a number added or multiplied in (ParameterModifyAction).
/// Deactivation does nothing: the value stays, as the standard's does.
class ParameterEffect : public WorldEffect {
public:
    enum class Op { set, add, multiply };
    /// Throws std::invalid_argument for a null store, an undeclared parameter, or a text operand
    /// of add / multiply.
    ParameterEffect(std::shared_ptr<ScenarioParameters> parameters, std::string name, Op op,
                    ScenarioParameters::Value value);

    void apply(WorldScope& scope) override;
    void remove(WorldScope& /*scope*/) override {}
    std::string describe() const override;

private:
    std::shared_ptr<ScenarioParameters> parameters_;
    std::string name_;
    Op op_;
    ScenarioParameters::Value value_;
};

}  // namespace sbsim::storyboard
