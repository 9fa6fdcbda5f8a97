#pragma once

#include <cstddef>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::traffic {

/// SUMO's printed output, sorted: warnings are counted by kind and only the first few of each kind
/// reach stderr (a city scenario prints dozens of near-identical "performs emergency braking"
/// lines), every warning goes to an optional log, everything else SUMO printed passes through.
/// A warning's kind is its text with quoted names and numbers blanked out, so "Vehicle 'a' performs
/// emergency braking ... time=12.00." and the same for vehicle 'b' at 40 s are one kind.
class SBSIM_API SumoWarnings {
public:
    struct Kind {
        std::string pattern;  ///< the text with '…' for names and # for numbers
        std::size_t count = 0;
    };

    /// `shown`: how many warnings of each kind go to `out` (the rest are only counted);
    /// SIZE_MAX shows all (--verbose).
    explicit SumoWarnings(std::size_t shown = 3, std::FILE* out = stderr) : shown_(shown), out_(out) {}

    /// Every warning, as SUMO printed it, also goes here (--sumo-log); nullptr: nowhere.
    void setLog(std::ostream* log) { log_ = log; }
    /// Takes what SUMO printed during one call (load, step).
    void take(std::string_view printed);

    std::size_t total() const { return total_; }
    /// By number of warnings, most first (ties: the first seen first).
    std::vector<Kind> kinds() const;
    /// A warning's kind (exposed for tests).
    static std::string kindOf(std::string_view message);

private:
    void warning(const std::string& message);

    std::size_t shown_;
    std::FILE* out_;
    std::ostream* log_ = nullptr;
    std::map<std::string, std::size_t> index_;  // pattern -> position in kinds_
    std::vector<Kind> kinds_;                   // in order of first appearance
    std::size_t total_ = 0;
};

}  // namespace sbsim::traffic
