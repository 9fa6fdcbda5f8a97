#include "sbsim/traffic/StderrCapture.h"

#include <fcntl.h>
#include <unistd.h>

#include <iostream>

namespace sbsim::traffic {

namespace {
void flushStderr() {
    std::cerr.flush();
    std::fflush(stderr);
}
}  // namespace

StderrCapture::StderrCapture() : file_(std::tmpfile()) {}  // none: errors simply stay on stderr

StderrCapture::~StderrCapture() {
    stop();
    if (file_ != nullptr) std::fclose(file_);
}

void StderrCapture::start() {
    if (file_ == nullptr || savedFd_ >= 0) return;
    flushStderr();
    savedFd_ = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
    if (savedFd_ >= 0 && dup2(fileno(file_), STDERR_FILENO) < 0) {
        close(savedFd_);
        savedFd_ = -1;
    }
}

std::string StderrCapture::stop() {
    if (savedFd_ < 0) return {};
    flushStderr();
    dup2(savedFd_, STDERR_FILENO);
    close(savedFd_);
    savedFd_ = -1;
    // Usually nothing was written: one lseek tells.
    const int fd = fileno(file_);
    const off_t size = lseek(fd, 0, SEEK_END);
    if (size <= 0) return {};
    std::string text(static_cast<std::size_t>(size), '\0');
    const ssize_t n = pread(fd, text.data(), text.size(), 0);
    text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    // Empty again for the next start(); the descriptor's offset is shared with stderr's writes.
    if (ftruncate(fd, 0) != 0) text += "\n(sbsim: cannot reuse the capture file)";
    lseek(fd, 0, SEEK_SET);
    return text;
}

}  // namespace sbsim::traffic
