#include "sbsim/app/Subcommands.h"

#include "sbsim/app/CheckCommand.h"

namespace sbsim::app {

std::vector<std::unique_ptr<Subcommand>> makeSubcommands() {
    std::vector<std::unique_ptr<Subcommand>> all;
    // One line per subcommand.
    all.push_back(std::make_unique<CheckCommand>());
    return all;
}

}  // namespace sbsim::app
