#pragma once

#include "sbsim/app/CommandLine.h"

namespace sbsim::app {

/// `sbsim [options]`: runs SUMO with the storyboard and the services as the options say, then
/// prints the summary. Returns the exit code (0, or 130 when interrupted); throws UsageError or
/// InputError for bad input, other exceptions for failures during the run.
int runSimulation(const CommandLine& options);

}  // namespace sbsim::app
