#pragma once

#include <csignal>

#include "sbsim/kernel/Signal.h"

namespace sbsim::kernel {
class Simulation;
}

namespace sbsim::app {

/// Ctrl-C (SIGINT) or SIGTERM during a run: the run stops after the current step, finishes its
/// modules and closes SUMO, so outputs are complete; a second Ctrl-C ends the process at once.
/// Installed for the guard's lifetime; checked on every SUMO step.
class Interruption : public kernel::Listener {
public:
    explicit Interruption(kernel::Simulation& sim);
    ~Interruption() override;
    Interruption(const Interruption&) = delete;
    Interruption& operator=(const Interruption&) = delete;

    static bool requested();
    void receiveSignal(kernel::Module& source, kernel::SignalId id, const kernel::Object& value) override;

private:
    kernel::Simulation& sim_;
    struct sigaction previousInt_ {};
    struct sigaction previousTerm_ {};
};

}  // namespace sbsim::app
