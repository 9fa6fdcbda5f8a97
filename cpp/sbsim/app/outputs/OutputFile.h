#pragma once

#include <ext/stdio_filebuf.h>

#include <filesystem>
#include <initializer_list>
#include <memory>
#include <ostream>
#include <string>

namespace sbsim::app {

class FileLedger;

/// An output file of the run (--events; later outputs use it too), written so that it never
/// destroys an input and never looks complete when it is not. The data goes to
/// `<name>.incomplete` beside the target, and commit() renames it to `<name>` when the run has
/// ended normally; a run that fails, is interrupted or is killed leaves `<name>.incomplete`, and
/// whatever was at `<name>` before stays as it was. A target that exists and is not a regular
/// file (/dev/null, a FIFO, a terminal) is written directly. Every problem is an OutputError
/// naming the option and the file.
class OutputFile {
public:
    static constexpr const char* kIncompleteSuffix = ".incomplete";

    /// Claims the target (and its `.incomplete` file) in `files`, so neither may be an input or
    /// another output, then opens the file to write.
    OutputFile(const std::string& option, const std::filesystem::path& path, FileLedger& files);
    /// Without commit(): closes the file, leaving it incomplete.
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::ostream& stream() { return *stream_; }
    /// The open file, for a writer of its own (a child process writing Parquet); the stream then
    /// stays unused.
    int descriptor() const { return fd_; }
    /// Throws OutputError if a write has failed (a full disk, a closed pipe).
    void check();
    /// Flushes everything to the disk and renames the file into place; throws OutputError.
    void commit();
    /// commit() in two halves, for a run's outputs to be committed together (commitTogether):
    /// prepare() flushes, syncs and closes the file, throwing OutputError for any failed write;
    /// publish() renames it into place.
    void prepare();
    void publish();

private:
    /// The file's buffer, keeping the error of its first failed write (errno is overwritten by
    /// whatever runs between the write and the check).
    class Buffer : public __gnu_cxx::stdio_filebuf<char> {
    public:
        using stdio_filebuf::stdio_filebuf;
        int firstError() const { return firstError_; }

    protected:
        int_type overflow(int_type c) override;
        std::streamsize xsputn(const char* s, std::streamsize n) override;
        int sync() override;

    private:
        template <typename F>
        auto keepingError(F write);
        int firstError_ = 0;
    };

    [[noreturn]] void fail(int error) const;

    std::string option_;
    std::filesystem::path path_;     ///< as given, for messages
    std::filesystem::path target_;   ///< where the finished file goes (symlinks resolved)
    std::filesystem::path writing_;  ///< the file being written: target_ + ".incomplete", or target_
    int fd_ = -1;
    std::unique_ptr<Buffer> buffer_;
    std::unique_ptr<std::ostream> stream_;
    bool committed_ = false;
    bool prepared_ = false;
};

/// Commits the given outputs (null ones skipped) all or none: every one is prepared first, so a
/// write that failed in any (a full disk, a closed pipe) leaves them all `.incomplete`; only then
/// are they renamed into place.
void commitTogether(std::initializer_list<OutputFile*> outputs);

}  // namespace sbsim::app
