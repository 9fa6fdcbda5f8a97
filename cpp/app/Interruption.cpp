#include "sbsim/app/Interruption.h"

#include <atomic>

#include "sbsim/kernel/Simulation.h"

namespace sbsim::app {

namespace {
std::atomic<bool> interrupted{false};

extern "C" void onInterrupt(int signal) {
    interrupted.store(true);
    std::signal(signal, SIG_DFL);  // a second one ends the process the usual way
}
}  // namespace

Interruption::Interruption(kernel::Simulation& sim) : sim_(sim) {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previousInt_);
    sigaction(SIGTERM, &action, &previousTerm_);
}

Interruption::~Interruption() {
    sigaction(SIGINT, &previousInt_, nullptr);
    sigaction(SIGTERM, &previousTerm_, nullptr);
}

bool Interruption::requested() { return interrupted.load(); }

void Interruption::receiveSignal(kernel::Module&, kernel::SignalId, const kernel::Object&) {
    if (requested()) sim_.stop();
}

}  // namespace sbsim::app
