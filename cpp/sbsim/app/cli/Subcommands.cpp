#include "sbsim/app/cli/Subcommands.h"

#include "sbsim/app/run/CheckCommand.h"
#include "sbsim/app/run/RunCommand.h"

namespace sbsim::app {

std::vector<std::unique_ptr<Subcommand>> makeSubcommands() {
    std::vector<std::unique_ptr<Subcommand>> all;
    // One line per subcommand; the run first.
    all.push_back(std::make_unique<RunCommand>());
    all.push_back(std::make_unique<CheckCommand>());
    return all;
}

Subcommand& defaultSubcommand(const std::vector<std::unique_ptr<Subcommand>>& all) { return *all.front(); }

}  // namespace sbsim::app
