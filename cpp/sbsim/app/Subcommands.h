#pragma once

#include <memory>
#include <vector>

#include "sbsim/app/Subcommand.h"

namespace sbsim::app {

/// Every subcommand sbsim has, in the order sbsim --help lists them.
std::vector<std::unique_ptr<Subcommand>> makeSubcommands();

}  // namespace sbsim::app
