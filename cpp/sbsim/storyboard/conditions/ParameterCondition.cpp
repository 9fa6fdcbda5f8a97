#include "sbsim/storyboard/conditions/ParameterCondition.h"

#include <fmt/format.h>

#include <stdexcept>

namespace sbsim::storyboard {

namespace {
const char* ruleName(ScenarioParameters::Rule r) {
    using R = ScenarioParameters::Rule;
    switch (r) {
        case R::greaterThan:
            return ">";
        case R::lessThan:
            return "<";
        case R::equalTo:
            return "==";
        case R::greaterOrEqual:
            return ">=";
        case R::lessOrEqual:
            return "<=";
        case R::notEqualTo:
            return "!=";
    }
    return "?";
}
}  // namespace

ParameterCondition::ParameterCondition(std::shared_ptr<ScenarioParameters> parameters, std::string name,
                                       ScenarioParameters::Rule rule, ScenarioParameters::Value value)
    : parameters_(std::move(parameters)), name_(std::move(name)), rule_(rule), value_(std::move(value)) {
    if (!parameters_) throw std::invalid_argument("ParameterCondition: the parameters are null");
    if (!parameters_->has(name_))
        throw std::invalid_argument(fmt::format("ParameterCondition: no parameter '{}'", name_));
}

std::string ParameterCondition::describe() const {
    return fmt::format("ParameterCondition({} {} {})", name_, ruleName(rule_), ScenarioParameters::describe(value_));
}

}  // namespace sbsim::storyboard
