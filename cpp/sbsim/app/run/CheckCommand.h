#pragma once

#include "sbsim/app/cli/Subcommand.h"

namespace sbsim::app {

/// `sbsim check --story S --sumocfg C`: loads the network and the script, registers the stories
/// and runs nothing. Prints each story as an indented condition tree with its effects, and warns
/// about what likely does not do what was meant (an area outside the network, naming the frame
/// that would have fitted; unknown car ids; time windows outside the run; LimitCondition(0);
/// conjunctions of disjoint time windows; two effects of one domain in a story). Exit 0 when
/// clean, 2 on errors, 1 on warnings with --strict; --json prints the same as one JSON document.
class CheckCommand : public Subcommand {
public:
    std::string name() const override { return "check"; }
    std::string description() const override {
        return "load the network and the story, print the stories and warn about likely mistakes; run nothing";
    }
    void declareOptions(CLI::App& command) override;
    int run(const CommandLine& options) override;

private:
    bool strict_ = false;
    bool json_ = false;
};

}  // namespace sbsim::app
