#include "sbsim/app/run/Interruption.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>

#include "sbsim/kernel/StopRequest.h"
#include "sbsim/python/PythonRuntime.h"

namespace sbsim::app {

namespace {

std::atomic<int> signalsReceived{0};
/// A copy of the original stderr: SUMO's messages are captured by redirecting descriptor 2, and
/// the second signal's message must still reach the terminal.
int originalStderr = -1;

// Only async-signal-safe calls here.
extern "C" void onSignal(int) {
    if (signalsReceived.fetch_add(1) == 0) {
        kernel::StopRequest::request();  // long C++ loops give up at their next safe point
        python::PythonRuntime::interruptFromSignalHandler();
        return;
    }
    constexpr char kMessage[] = "sbsim: interrupted again: exiting at once\n";
    if (originalStderr >= 0) (void)!write(originalStderr, kMessage, sizeof kMessage - 1);
    _exit(130);
}

void installHandlers() {
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    // Restarted system calls: a signal must not make SUMO's or the program's own reads and writes
    // fail with EINTR. Sleeps and waits are never restarted, so Python still wakes up to raise.
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

bool installed(int signal) {
    struct sigaction current {};
    sigaction(signal, nullptr, &current);
    return (current.sa_flags & SA_SIGINFO) == 0 && current.sa_handler == onSignal;
}

}  // namespace

void Interruption::install() {
    if (originalStderr < 0) originalStderr = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
    installHandlers();
    // A reader that goes away (sbsim ... | head) is not a reason to die: writes get EPIPE, which
    // the progress and summary ignore and an output file reports.
    std::signal(SIGPIPE, SIG_IGN);
}

bool Interruption::requested() { return signalsReceived.load() > 0; }

void Interruption::reassert() {
    if (!installed(SIGINT) || !installed(SIGTERM)) installHandlers();
}

void Interruption::checkpoint(const std::string& phase) {
    if (requested()) throw Interrupted(phase);
}

}  // namespace sbsim::app
