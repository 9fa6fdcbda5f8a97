#pragma once

#include <memory>
#include <vector>

#include "sbsim/app/cli/Subcommand.h"

namespace sbsim::app {

/// Every subcommand sbsim has, in the order sbsim --help lists them; the first is the run.
std::vector<std::unique_ptr<Subcommand>> makeSubcommands();
/// What `sbsim [options]` without a subcommand does: the run (the first of `all`).
Subcommand& defaultSubcommand(const std::vector<std::unique_ptr<Subcommand>>& all);

}  // namespace sbsim::app
