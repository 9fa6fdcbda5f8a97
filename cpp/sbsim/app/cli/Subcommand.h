#pragma once

#include <string>

namespace CLI {
class App;
}

namespace sbsim::app {

struct CommandLine;

/// A `sbsim <name> [options] [-- SUMO options]` command beside the plain run (`sbsim [options]`).
/// Adding one: a class implementing this in its own file under cpp/sbsim/app/run/, and one line in
/// cli/Subcommands.cpp (plus its source in cpp/sbsim/app/CMakeLists.txt).
class Subcommand {
public:
    virtual ~Subcommand() = default;

    virtual std::string name() const = 0;
    /// One line for sbsim --help.
    virtual std::string description() const = 0;
    /// Declares the subcommand's own options on `command` (sbsim's subcommand named name()). The
    /// run's options (--sumocfg, --story, ...) are accepted after the name too and reach run().
    virtual void declareOptions(CLI::App& command) { (void)command; }
    /// Runs after the whole command line was parsed and checked; returns the exit code. Throws
    /// UsageError or InputError (BadInput.h) for bad input: one line on stderr, exit code 2.
    virtual int run(const CommandLine& options) = 0;
};

}  // namespace sbsim::app
