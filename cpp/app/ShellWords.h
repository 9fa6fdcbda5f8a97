#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sbsim::app {

/// Splits `text` into words as a POSIX shell would (whitespace, '…', "…", backslash escapes;
/// no expansions), so `--sumo-option "--begin 600 --load-state 's t.xml'"` works as typed.
/// Throws std::invalid_argument on an unterminated quote.
std::vector<std::string> splitShellWords(std::string_view text);

}  // namespace sbsim::app
