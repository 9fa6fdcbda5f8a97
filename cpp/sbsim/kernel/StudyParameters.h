#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::kernel {

/// A `--param NAME=VALUE` that does not parse: no `=`, an empty or odd name, a name given twice.
class SBSIM_API StudyParameterError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// The parameters of one run of a study (`--param rain_speed=10`), shared by everything in the
/// run: the story script (`board.parameters`), services (`Service::studyParameter`) and the
/// summary. Values are typed as written: `true`/`false` a bool, a whole number an integer, any
/// other number a float, everything else text. Reads are recorded so that the run can warn about
/// a parameter nobody read (a misspelt name in a sweep would otherwise pass unnoticed).
class SBSIM_API StudyParameters {
public:
    using Value = std::variant<bool, std::int64_t, double, std::string>;

    /// Adds `NAME=VALUE`; throws StudyParameterError naming what is wrong.
    void add(std::string_view assignment);
    /// The value of `name` (and records the read), or nothing.
    std::optional<Value> get(const std::string& name) const;
    bool contains(const std::string& name) const { return values_.count(name) != 0; }
    /// Every parameter, by name, without recording reads (for the summary).
    const std::map<std::string, Value>& all() const { return values_; }
    /// Names never read through get(), in name order.
    std::vector<std::string> unread() const;
    bool empty() const { return values_.empty(); }

    /// The value as parsed from its text (exposed for tests).
    static Value parse(std::string_view text);
    /// The value as the summary writes it (a float keeps a decimal point: 10.0, not 10).
    static std::string format(const Value& value);

private:
    std::map<std::string, Value> values_;
    mutable std::set<std::string> read_;
};

}  // namespace sbsim::kernel
