#pragma once

#include <csignal>
#include <stdexcept>
#include <string>

namespace sbsim::app {

/// The program's one signal policy, for the whole life of the process. The first SIGINT or
/// SIGTERM, whatever is running (SUMO loading, createStories, a step, a custom condition), asks
/// the run to stop at its next safe point: the program checks requested() between phases and
/// after every step, and Python code running at that moment gets KeyboardInterrupt. The run then
/// ends with exit code 130 and its outputs left marked incomplete. A second signal ends the
/// process at once, also with code 130. SIGPIPE is ignored: a closed pipe on stdout or stderr
/// loses the progress and summary, not the run (exit 0); an output file's write fails with exit 2.
/// SIGHUP keeps its default (the process ends, outputs left `.incomplete`).
class Interruption {
public:
    /// Installs the handlers; called once, first thing in the program.
    static void install();
    static bool requested();
    /// Installs the handlers again if something (a story calling signal.signal) replaced them.
    static void reassert();
    /// Throws Interrupted if an interruption was requested; `phase` completes "interrupted ...".
    static void checkpoint(const std::string& phase);
};

/// The run stopped at a safe point before stepping began, because of SIGINT or SIGTERM: the
/// program prints "sbsim: interrupted <what()>" and exits with code 130.
class Interrupted : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace sbsim::app
