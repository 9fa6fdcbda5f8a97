#pragma once

#include <memory>
#include <string>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/ScenarioParameters.h"

namespace sbsim::storyboard {

/// OpenSCENARIO's ParameterCondition: a storyboard parameter compares to a value by a rule, as the
/// parameter stands now (ParameterEffect changes it during the run). Depends on no vehicle.
class ParameterCondition : public Condition {
public:
    /// Throws std::invalid_argument for a null store or a parameter it does not declare.
    ParameterCondition(std::shared_ptr<ScenarioParameters> parameters, std::string name, ScenarioParameters::Rule rule,
                       ScenarioParameters::Value value);

    ConditionResult test(const EvaluationContext& /*ctx*/, VehicleIndex /*ego*/) override {
        return parameters_->compare(name_, rule_, value_);
    }
    traffic::SnapshotColumns columns() const override { return {}; }
    bool timeOnly() const override { return true; }
    std::string describe() const override;

private:
    std::shared_ptr<ScenarioParameters> parameters_;
    std::string name_;
    ScenarioParameters::Rule rule_;
    ScenarioParameters::Value value_;
};

}  // namespace sbsim::storyboard
