#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sbsim::app {

/// Checks a state SUMO is to load (--load-state) before SUMO reads it: SUMO crashes on some
/// malformed states, such as one with vehicles on a lane its network does not have. The file
/// must be XML (plain or gzip) with a <snapshot> root and a time sbsim can run at, and every
/// <lane> and <edge> in it must be in the network (when `netFiles` can be read: a broken network
/// is left for SUMO to report). Throws InputError naming `source`, the file and the line.
void checkSumoState(const std::string& source, const std::filesystem::path& state,
                    const std::vector<std::filesystem::path>& netFiles);

}  // namespace sbsim::app
