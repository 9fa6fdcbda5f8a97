#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sbsim::app {

/// The files a run reads and writes, each with what names it (an option, or a file and its
/// option). Inputs are checked before anything opens them; an output is refused when it is the
/// same file as an input or as another output (std::filesystem::equivalent: symlinks and hard
/// links included), so that writing it can never destroy one. Whichever comes first: an input
/// recorded after an output is checked against it too, so no feature's input can slip through
/// by being read late.
class FileLedger {
public:
    /// An input named on the command line: it must be a regular, readable file. Checked before
    /// anything opens it, so a FIFO cannot block. Throws InputError naming `option`.
    void requireInput(const std::string& option, const std::filesystem::path& path);
    /// A file an input names that SUMO opens itself (a sumocfg's net or route files): if it
    /// exists it must be a regular file; a missing one is left for SUMO to report.
    void addReferencedInput(const std::string& source, const std::filesystem::path& path);
    /// Records an output; throws OutputError if `path` is an input or an output recorded before.
    void claimOutput(const std::string& option, const std::filesystem::path& path);

private:
    struct File {
        std::string source;
        std::filesystem::path path;
    };
    /// Records an input; throws OutputError if an output claimed before is the same file.
    void addInput(const std::string& source, const std::filesystem::path& path);

    std::vector<File> inputs_;
    std::vector<File> outputs_;
};

/// Throws InputError unless `path` is a regular file that can be read (a missing file, a
/// directory, a FIFO or device, an unreadable file), naming `option` and the path.
void requireReadableFile(const std::string& option, const std::filesystem::path& path);

}  // namespace sbsim::app
