#include "sbsim/app/inputs/FileLedger.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "sbsim/app/cli/BadInput.h"

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {

const char* kindOf(fs::file_type type) {
    switch (type) {
        case fs::file_type::fifo:
            return "a FIFO";
        case fs::file_type::socket:
            return "a socket";
        case fs::file_type::block:
            return "a block device";
        case fs::file_type::character:
            return "a character device";
        default:
            return "not a regular file";
    }
}

/// Whether `a` and `b` name the same file: the same inode when both exist, else the same path
/// once made absolute with symlinks resolved (outputs are claimed before they exist).
bool sameFile(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
    const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
    const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
    return !ec && ca == cb;
}

}  // namespace

void requireReadableFile(const std::string& option, const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);  // follows symlinks
    if (status.type() == fs::file_type::not_found) {
        throw InputError(fmt::format("{}: no such file '{}'", option, path.string()));
    }
    if (ec) throw InputError(fmt::format("{}: cannot read '{}': {}", option, path.string(), ec.message()));
    if (fs::is_directory(status)) {
        throw InputError(fmt::format("{}: '{}' is a directory, not a file", option, path.string()));
    }
    if (!fs::is_regular_file(status)) {
        throw InputError(fmt::format("{}: '{}' is {}; sbsim reads regular files only", option, path.string(),
                                     kindOf(status.type())));
    }
    // A regular file: opening it cannot block.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw InputError(fmt::format("{}: cannot read '{}': {}", option, path.string(), std::strerror(errno)));
    ::close(fd);
}

void FileLedger::requireInput(const std::string& option, const fs::path& path) {
    requireReadableFile(option, path);
    addInput(option, path);
}

void FileLedger::addInput(const std::string& source, const fs::path& path) {
    // Recorded once (a service's file is asked for again once the services are loaded).
    for (const File& input : inputs_) {
        if (input.path == path) return;
    }
    // An input found after an output was claimed (a file one feature reads late) is still one.
    for (const File& output : outputs_) {
        if (!sameFile(path, output.path)) continue;
        throw OutputError(
            fmt::format("{}: '{}' is the same file as the input '{}' ({}); an output must not overwrite it",
                        output.source, output.path.string(), path.string(), source));
    }
    inputs_.push_back({source, path});
}

void FileLedger::addReferencedInput(const std::string& source, const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found) return;  // SUMO names it in its own message
    if (fs::is_directory(status)) {
        throw InputError(fmt::format("{}: '{}' is a directory, not a file", source, path.string()));
    }
    if (!ec && !fs::is_regular_file(status)) {
        throw InputError(fmt::format("{}: '{}' is {}; sbsim reads regular files only", source, path.string(),
                                     kindOf(status.type())));
    }
    addInput(source, path);
}

void FileLedger::claimOutput(const std::string& option, const fs::path& path) {
    for (const File& input : inputs_) {
        if (!sameFile(path, input.path)) continue;
        throw OutputError(
            fmt::format("{}: '{}' is the same file as the input '{}' ({}); an output must not overwrite it", option,
                        path.string(), input.path.string(), input.source));
    }
    for (const File& output : outputs_) {
        if (!sameFile(path, output.path)) continue;
        throw OutputError(
            fmt::format("{}: '{}' is the same file as the output of {}", option, path.string(), output.source));
    }
    outputs_.push_back({option, path});
}

}  // namespace sbsim::app
