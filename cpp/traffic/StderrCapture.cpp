#include "sbsim/traffic/StderrCapture.h"

#include <unistd.h>

#include <iostream>

namespace sbsim::traffic {

StderrCapture::StderrCapture() {
    std::cerr.flush();
    std::fflush(stderr);
    file_ = std::tmpfile();
    if (file_ == nullptr) return;  // cannot capture: errors simply stay on stderr
    savedFd_ = dup(STDERR_FILENO);
    if (savedFd_ < 0 || dup2(fileno(file_), STDERR_FILENO) < 0) {
        if (savedFd_ >= 0) close(savedFd_);
        savedFd_ = -1;
        std::fclose(file_);
        file_ = nullptr;
    }
}

StderrCapture::~StderrCapture() { finish(); }

std::string StderrCapture::finish() {
    if (file_ == nullptr) return {};
    std::cerr.flush();
    std::fflush(stderr);
    dup2(savedFd_, STDERR_FILENO);
    close(savedFd_);
    std::string text;
    std::rewind(file_);
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, file_)) > 0;) text.append(buf, n);
    std::fclose(file_);
    file_ = nullptr;
    return text;
}

}  // namespace sbsim::traffic
