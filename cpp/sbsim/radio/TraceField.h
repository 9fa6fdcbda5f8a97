#pragma once

#include <cstdint>
#include <string>
#include <variant>

namespace sbsim::radio {

/// One extra field a message adds to its lines in the message trace (--messages), e.g. a DENM's
/// cause code: a name and a number or a text.
struct TraceField {
    std::string name;
    std::variant<std::int64_t, double, std::string> value;
};

}  // namespace sbsim::radio
