#pragma once

#include <cstdio>
#include <string>

namespace sbsim::traffic {

/// Redirects file descriptor 2 into a temporary file for its lifetime. SUMO reports load errors
/// only by printing them to stderr (the exception just says "Process Error"), so the bridge
/// captures them to build one clear error line. Restores stderr when destroyed.
class StderrCapture {
public:
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    /// Restores stderr and returns everything written meanwhile.
    std::string finish();

private:
    std::FILE* file_ = nullptr;
    int savedFd_ = -1;
};

}  // namespace sbsim::traffic
