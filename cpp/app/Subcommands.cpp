#include "sbsim/app/Subcommands.h"

namespace sbsim::app {

std::vector<std::unique_ptr<Subcommand>> makeSubcommands() {
    std::vector<std::unique_ptr<Subcommand>> all;
    // One line per subcommand, e.g. all.push_back(std::make_unique<CheckCommand>());
    return all;
}

}  // namespace sbsim::app
