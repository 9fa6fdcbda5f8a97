#pragma once

#include <map>
#include <string>
#include <variant>

#include "sbsim/kernel/Export.h"

namespace sbsim::storyboard {

/// The global parameters of an OpenSCENARIO storyboard while it runs: what ParameterSetAction and
/// ParameterModifyAction change (ParameterEffect) and ParameterCondition reads. A value is a number
/// (double, integer and boolean parameters: true is 1) or a text.
class SBSIM_API ScenarioParameters {
public:
    using Value = std::variant<double, std::string>;
    enum class Rule { greaterThan, lessThan, equalTo, greaterOrEqual, lessOrEqual, notEqualTo };

    /// Declares `name` with its initial value (a second declaration replaces it).
    void declare(const std::string& name, Value value) { values_[name] = std::move(value); }
    bool has(const std::string& name) const { return values_.contains(name); }
    /// Throws std::out_of_range for an undeclared name.
    const Value& get(const std::string& name) const;
    /// Throws std::out_of_range for an undeclared name, std::invalid_argument for a text given to
    /// a number or a number to a text.
    void set(const std::string& name, const Value& value);
    /// value += operand (`multiply`: value *= operand); throws std::invalid_argument for a text.
    void modify(const std::string& name, double operand, bool multiply);
    /// Whether `name`'s value compares to `value` by `rule` (numbers as numbers, texts as texts;
    /// a number against a text is false, notEqualTo true).
    bool compare(const std::string& name, Rule rule, const Value& value) const;

    static std::string describe(const Value& v);

private:
    std::map<std::string, Value, std::less<>> values_;
};

}  // namespace sbsim::storyboard
