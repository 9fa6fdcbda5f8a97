#pragma once

#include <map>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::services {

struct ServiceSpec;

/// What one attribute of a bundled service or DEN use case takes: its kind and, for numbers, its
/// closed range. The one place these are written (README, "Service attributes", lists the same).
struct SBSIM_API AttributeRule {
    enum class Kind {
        Number,    ///< a finite number from min to max
        Whole,     ///< a whole number from min to max (no fraction to truncate)
        Duration,  ///< seconds, ServiceSpec::kMinDurationSeconds to kMaxDurationSeconds
        Boolean,   ///< true, false, 1 or 0
        Text,      ///< any text
    };
    Kind kind = Kind::Text;
    double min = 0;
    double max = 0;
    const char* unit = "";

    /// What a value must be, for messages: "a whole number from 0 to 255".
    std::string expected() const;
};

/// The attributes of every bundled service and use case, by type name; types not listed (a
/// plugin's, a test's) are not checked. Every type takes Artery's `name` (a label).
SBSIM_API const std::map<std::string, std::map<std::string, AttributeRule>>& attributeRules();

/// Checks `spec`'s attributes against its type's rules (nothing for a type without any): an
/// unknown attribute (a misspelling would be silently ignored), a value of the wrong kind or out of
/// range, or attributes that contradict each other (a minimum above its maximum) throws
/// ServicesConfigError naming the file, line, type and attribute.
SBSIM_API void checkAttributes(const ServiceSpec& spec);

}  // namespace sbsim::services
