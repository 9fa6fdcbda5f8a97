#pragma once

#include <optional>
#include <string_view>

namespace sbsim::storyboard {

/// How a condition compares a value with its threshold (OpenSCENARIO's Rule, by its names).
enum class ComparisonRule { LessThan, LessOrEqual, EqualTo, GreaterOrEqual, GreaterThan, NotEqualTo };

/// OpenSCENARIO's name: "lessThan", "lessOrEqual", "equalTo", "greaterOrEqual", "greaterThan",
/// "notEqualTo".
constexpr std::string_view ruleName(ComparisonRule rule) {
    switch (rule) {
        case ComparisonRule::LessThan:
            return "lessThan";
        case ComparisonRule::LessOrEqual:
            return "lessOrEqual";
        case ComparisonRule::EqualTo:
            return "equalTo";
        case ComparisonRule::GreaterOrEqual:
            return "greaterOrEqual";
        case ComparisonRule::GreaterThan:
            return "greaterThan";
        case ComparisonRule::NotEqualTo:
            return "notEqualTo";
    }
    return "lessThan";
}

constexpr std::optional<ComparisonRule> ruleNamed(std::string_view name) {
    for (const ComparisonRule r :
         {ComparisonRule::LessThan, ComparisonRule::LessOrEqual, ComparisonRule::EqualTo,
          ComparisonRule::GreaterOrEqual, ComparisonRule::GreaterThan, ComparisonRule::NotEqualTo}) {
        if (ruleName(r) == name) return r;
    }
    return std::nullopt;
}

/// `value` against `threshold`; equalTo (and notEqualTo) within `tolerance`, since measured values
/// hardly ever equal a threshold exactly.
constexpr bool compare(ComparisonRule rule, double value, double threshold, double tolerance) {
    switch (rule) {
        case ComparisonRule::LessThan:
            return value < threshold;
        case ComparisonRule::LessOrEqual:
            return value <= threshold;
        case ComparisonRule::EqualTo:
            return value >= threshold - tolerance && value <= threshold + tolerance;
        case ComparisonRule::GreaterOrEqual:
            return value >= threshold;
        case ComparisonRule::GreaterThan:
            return value > threshold;
        case ComparisonRule::NotEqualTo:
            return value < threshold - tolerance || value > threshold + tolerance;
    }
    return false;
}

}  // namespace sbsim::storyboard
