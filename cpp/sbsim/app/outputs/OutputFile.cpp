#include "sbsim/app/outputs/OutputFile.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/inputs/FileLedger.h"

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {
constexpr std::size_t kBufferSize = 1 << 16;

/// `target` + ".incomplete", shortened when the name would pass the file system's limit (a
/// 250-character name is a valid output, its temporary name must be too).
fs::path incompleteName(const fs::path& target) {
    const std::string name = target.filename().string();
    const std::string suffix = OutputFile::kIncompleteSuffix;
    const long limit = ::pathconf(target.parent_path().c_str(), _PC_NAME_MAX);
    const std::size_t max = limit > 0 ? static_cast<std::size_t>(limit) : 255;
    if (name.size() + suffix.size() <= max || max <= suffix.size()) return fs::path(target.string() + suffix);
    return target.parent_path() / (name.substr(0, max - suffix.size()) + suffix);
}

/// Creates `path` to write, never through whatever is there: O_EXCL|O_NOFOLLOW, so a symlink or
/// file planted at the temporary name cannot redirect or truncate another file. A stale one (a
/// file or link left by an earlier run) is unlinked, which removes the link, not what it points
/// to, and the creation is tried once more. Returns -1 with errno set.
int createExclusively(const fs::path& path) {
    constexpr int kFlags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
    int fd = ::open(path.c_str(), kFlags, 0666);
    if (fd < 0 && errno == EEXIST) {
        if (::unlink(path.c_str()) != 0) return -1;
        fd = ::open(path.c_str(), kFlags, 0666);
    }
    return fd;
}
}  // namespace

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
    : option_(option), path_(path) {
    if (path.empty()) throw OutputError(fmt::format("{}: the file name is empty", option));
    std::error_code ec;
    // Resolved now: a story that changes the working folder must not move the finished file.
    target_ = fs::absolute(path, ec);
    if (ec) throw OutputError(fmt::format("{}: cannot resolve '{}': {}", option, path.string(), ec.message()));
    // Writing through a symlink replaces the file it points to, not the link.
    if (fs::is_symlink(target_, ec)) target_ = fs::weakly_canonical(target_, ec);
    const fs::file_status status = fs::status(target_, ec);
    if (fs::is_directory(status)) {
        throw OutputError(fmt::format("{}: cannot write '{}': it is a directory", option, path.string()));
    }
    const bool direct = fs::exists(status) && !fs::is_regular_file(status);
    writing_ = direct ? target_ : incompleteName(target_);
    files.claimOutput(option, target_);
    if (!direct) files.claimOutput(option, writing_);

    // Non-blocking open: a FIFO nobody reads fails at once (ENXIO) instead of waiting.
    fd_ = direct ? ::open(writing_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC) : createExclusively(writing_);
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
    prepare();
    publish();
}

void OutputFile::prepare() {
    if (prepared_) return;
    stream_->flush();
    check();
    // On the disk before it gets its final name, so a crash cannot leave a complete-looking
    // file with missing data. Devices and pipes cannot sync; that is fine for them.
    const bool renamed = writing_ != target_;
    if (renamed && ::fsync(fd_) != 0) fail(errno);
    errno = 0;
    if (buffer_->close() == nullptr) fail(errno != 0 ? errno : EIO);
    committed_ = true;
    prepared_ = true;
}

void OutputFile::publish() {
    if (!prepared_) throw std::logic_error("OutputFile::publish() before prepare()");
    if (writing_ != target_ && std::rename(writing_.c_str(), target_.c_str()) != 0) fail(errno);
}

void commitTogether(std::initializer_list<OutputFile*> outputs) {
    for (OutputFile* output : outputs) {
        if (output != nullptr) output->prepare();
    }
    for (OutputFile* output : outputs) {
        if (output != nullptr) output->publish();
    }
}

}  // namespace sbsim::app
