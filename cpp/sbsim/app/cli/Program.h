#pragma once

#include <string>
#include <vector>

namespace sbsim::app {

/// The `sbsim` program: parses arguments, runs, and maps every failure to one line on stderr and
/// an exit code (0 ok, 2 bad input, SUMO's errors included, 130 interrupted, 1 an internal error). Never lets an
/// exception escape.
int runProgram(const std::vector<std::string>& args);

}  // namespace sbsim::app
