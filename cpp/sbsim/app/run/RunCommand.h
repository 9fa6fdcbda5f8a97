#pragma once

#include <string>

#include "sbsim/app/cli/CommandLine.h"
#include "sbsim/app/cli/Subcommand.h"

namespace sbsim::app {

/// `sbsim run [options]`, also plain `sbsim [options]`: runs SUMO with the storyboard and the
/// services as the options say, then prints the summary. Returns the exit code (0, or 130 when
/// interrupted); throws UsageError or InputError for bad input, other exceptions for failures
/// during the run.
class RunCommand : public Subcommand {
public:
    std::string name() const override { return "run"; }
    std::string description() const override {
        return "run the simulation (the default: 'sbsim [options]' is 'sbsim run [options]')";
    }
    int run(const CommandLine& options) override;
};

}  // namespace sbsim::app
