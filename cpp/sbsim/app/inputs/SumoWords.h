#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sbsim::app {

/// Splits one `--sumo-option` value into words as a POSIX shell would (wordexp(3): quotes,
/// backslashes, $VARIABLES, ~; no command substitution), so
/// `--sumo-option "--fcd-output 'a b.xml'"` works as typed. Throws UsageError naming
/// --sumo-option (an unbalanced quote, an unquoted `;`, `$(...)`, an unset variable).
std::vector<std::string> splitSumoOption(const std::string& text);

/// Takes SUMO's own `-c FILE` / `--configuration-file FILE` out of `sumoArgs` (SUMO refuses a
/// second one, and sbsim passes the configuration itself); returns the file if it was there.
/// Throws UsageError if it is given twice or without a file.
std::optional<std::filesystem::path> takeConfigurationFile(std::vector<std::string>& sumoArgs);

}  // namespace sbsim::app
