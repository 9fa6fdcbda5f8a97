#pragma once

#include <cstdio>
#include <string>

namespace sbsim::traffic {

/// Catches what is written to file descriptor 2 between start() and stop(), in a temporary file
/// kept for the object's lifetime. SUMO reports many errors only by printing them (the exception
/// just says "Process Error"), so the bridge captures its load and its every step to turn them
/// into one clear line. Restores stderr when destroyed.
class StderrCapture {
public:
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    /// Redirects stderr into the file (does nothing if the file could not be made).
    void start();
    /// Restores stderr and returns what was written since start().
    std::string stop();

private:
    std::FILE* file_ = nullptr;
    int savedFd_ = -1;
};

}  // namespace sbsim::traffic
