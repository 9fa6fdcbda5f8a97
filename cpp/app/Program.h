#pragma once

#include <string>
#include <vector>

namespace sbsim::app {

/// The `sbsim` program: parses arguments, runs, and maps every failure to one line on stderr and
/// an exit code (0 ok, 1 a failure during the run, 2 bad input). Never lets an exception escape.
int runProgram(const std::vector<std::string>& args);

}  // namespace sbsim::app
