#include "sbsim/storyboard/ScenarioParameters.h"

#include <fmt/format.h>

#include <stdexcept>

namespace sbsim::storyboard {

const ScenarioParameters::Value& ScenarioParameters::get(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end()) throw std::out_of_range(fmt::format("no parameter '{}' is declared", name));
    return it->second;
}

void ScenarioParameters::set(const std::string& name, const Value& value) {
    const Value& old = get(name);
    if (old.index() != value.index()) {
        throw std::invalid_argument(fmt::format("parameter '{}' holds a {}, not a {}", name,
                                                old.index() == 0 ? "number" : "text",
                                                value.index() == 0 ? "number" : "text"));
    }
    values_[name] = value;
}

void ScenarioParameters::modify(const std::string& name, double operand, bool multiply) {
    const Value& old = get(name);
    const double* number = std::get_if<double>(&old);
    if (number == nullptr) throw std::invalid_argument(fmt::format("parameter '{}' holds a text: no arithmetic", name));
    values_[name] = multiply ? *number * operand : *number + operand;
}

bool ScenarioParameters::compare(const std::string& name, Rule rule, const Value& value) const {
    const Value& held = get(name);
    if (held.index() != value.index()) return rule == Rule::notEqualTo;
    const auto cmp = [rule](const auto& a, const auto& b) {
        switch (rule) {
            case Rule::greaterThan:
                return a > b;
            case Rule::lessThan:
                return a < b;
            case Rule::equalTo:
                return a == b;
            case Rule::greaterOrEqual:
                return a >= b;
            case Rule::lessOrEqual:
                return a <= b;
            case Rule::notEqualTo:
                return a != b;
        }
        return false;
    };
    if (held.index() == 0) return cmp(std::get<double>(held), std::get<double>(value));
    return cmp(std::get<std::string>(held), std::get<std::string>(value));
}

std::string ScenarioParameters::describe(const Value& v) {
    if (const double* d = std::get_if<double>(&v)) return fmt::format("{:g}", *d);
    return "'" + std::get<std::string>(v) + "'";
}

}  // namespace sbsim::storyboard
