#pragma once

#include <string>
#include <string_view>

namespace sbsim::kernel {

/// `text` on one line: runs of white space (newlines included) become one space, trimmed. Error
/// messages from SUMO and Python span lines; sbsim reports every problem in one.
inline std::string oneLine(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    bool pendingSpace = false;
    for (const char c : text) {
        if (c == ' ' || c == '\n' || c == '\r' || c == '\t') {
            pendingSpace = !out.empty();
            continue;
        }
        if (pendingSpace) out.push_back(' ');
        pendingSpace = false;
        out.push_back(c);
    }
    return out;
}

}  // namespace sbsim::kernel
