#include "sbsim/app/outputs/OutputFile.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/inputs/FileLedger.h"

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {
constexpr std::size_t kBufferSize = 1 << 16;
}

template <typename F>
auto OutputFile::Buffer::keepingError(F write) {
    errno = 0;
    const auto result = write();
    if (errno != 0 && firstError_ == 0) firstError_ = errno;
    return result;
}

OutputFile::Buffer::int_type OutputFile::Buffer::overflow(int_type c) {
    return keepingError([&] { return stdio_filebuf::overflow(c); });
}

std::streamsize OutputFile::Buffer::xsputn(const char* s, std::streamsize n) {
    return keepingError([&] { return stdio_filebuf::xsputn(s, n); });
}

int OutputFile::Buffer::sync() {
    return keepingError([&] { return stdio_filebuf::sync(); });
}

OutputFile::OutputFile(const std::string& option, const fs::path& path, FileLedger& files)
    : option_(option), path_(path), target_(path) {
    if (path.empty()) throw OutputError(fmt::format("{}: the file name is empty", option));
    std::error_code ec;
    // Writing through a symlink replaces the file it points to, not the link.
    if (fs::is_symlink(path, ec)) target_ = fs::weakly_canonical(path, ec);
    const fs::file_status status = fs::status(target_, ec);
    if (fs::is_directory(status)) {
        throw OutputError(fmt::format("{}: cannot write '{}': it is a directory", option, path.string()));
    }
    const bool direct = fs::exists(status) && !fs::is_regular_file(status);
    writing_ = direct ? target_ : fs::path(target_.string() + kIncompleteSuffix);
    files.claimOutput(option, target_);
    if (!direct) files.claimOutput(option, writing_);

    // Non-blocking open: a FIFO nobody reads fails at once (ENXIO) instead of waiting.
    const int flags = direct ? O_WRONLY | O_NONBLOCK : O_WRONLY | O_CREAT | O_TRUNC;
    fd_ = ::open(writing_.c_str(), flags | O_CLOEXEC, 0666);
    if (fd_ < 0) fail(errno);
    if (direct) ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
    buffer_ = std::make_unique<Buffer>(fd_, std::ios::out, kBufferSize);
    stream_ = std::make_unique<std::ostream>(buffer_.get());
}

OutputFile::~OutputFile() {
    if (committed_ || buffer_ == nullptr) return;
    stream_->flush();
    buffer_->close();  // closes fd_
}

void OutputFile::fail(int error) const {
    const std::string why = error == ENXIO ? "no process reads it" : std::strerror(error);
    throw OutputError(fmt::format("{}: cannot write '{}': {}", option_, path_.string(), why));
}

void OutputFile::check() {
    if (stream_->good()) return;
    fail(buffer_->firstError() != 0 ? buffer_->firstError() : EIO);
}

void OutputFile::commit() {
    stream_->flush();
    check();
    // On the disk before it gets its final name, so a crash cannot leave a complete-looking
    // file with missing data. Devices and pipes cannot sync; that is fine for them.
    const bool renamed = writing_ != target_;
    if (renamed && ::fsync(fd_) != 0) fail(errno);
    errno = 0;
    if (buffer_->close() == nullptr) fail(errno != 0 ? errno : EIO);
    committed_ = true;
    if (renamed && std::rename(writing_.c_str(), target_.c_str()) != 0) fail(errno);
}

}  // namespace sbsim::app
