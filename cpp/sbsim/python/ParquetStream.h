#pragma once

#include <sys/types.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::python {

/// One column of a row group handed to a ParquetStream: float64, int64 or UTF-8 strings, any
/// value may be null. Kept as Arrow lays columns out (values, string offsets, one validity byte
/// a row), so the writer copies nothing it does not have to.
class SBSIM_API ParquetColumn {
public:
    enum class Type { Float64, Int64, String };

    ParquetColumn(std::string name, Type type) : name_(std::move(name)), type_(type) {}

    void append(double v);
    void append(std::int64_t v);
    void append(std::string_view v);
    void appendNull();
    void clear();

    const std::string& name() const { return name_; }
    Type type() const { return type_; }
    std::size_t size() const { return valid_.size(); }
    std::size_t nulls() const { return nulls_; }
    /// The bytes the column holds (what handing it over costs).
    std::size_t bytes() const;

private:
    friend class ParquetStream;
    std::string name_;
    Type type_;
    std::vector<double> doubles_;
    std::vector<std::int64_t> ints_;
    std::vector<std::int32_t> offsets_{0};
    std::string chars_;
    std::vector<std::uint8_t> valid_;
    std::size_t nulls_ = 0;
};

/// A Parquet file written row group by row group as a run goes, by pyarrow in a child Python (the
/// interpreter sbsim embeds, sys.executable): SUMO's wheel loads a libarrow of its own, which
/// pyarrow must not meet in this process (see StatisticsParquet). The child writes to the file
/// descriptor it is given, so the file stays the one the caller created (OutputFile), and
/// answers after each row group with the file's size. It ignores SIGINT and SIGTERM (its own
/// process group): sbsim decides when the file ends, and an interrupted run still closes it.
class SBSIM_API ParquetStream {
public:
    /// Thrown when the child cannot start or pyarrow is missing; what() is one line.
    class Unavailable : public std::runtime_error {
    public:
        using std::runtime_error::runtime_error;
    };
    /// Thrown when writing fails (a full disk, the child died); what() is one line.
    class WriteError : public std::runtime_error {
    public:
        using std::runtime_error::runtime_error;
    };

    /// Starts the child writing to `fd` (which stays the caller's); an interpreter must be
    /// running. Throws Unavailable.
    explicit ParquetStream(int fd);
    /// Without close(): ends the child (the file is left as far as it got).
    ~ParquetStream();
    ParquetStream(const ParquetStream&) = delete;
    ParquetStream& operator=(const ParquetStream&) = delete;

    /// Writes the columns (all of one length, the same names and types every time) as one row
    /// group; returns the file's size after it. Throws WriteError.
    std::uint64_t writeRowGroup(const std::vector<ParquetColumn>& columns);
    /// Writes the footer and waits for the child; returns the file's final size. Throws WriteError.
    std::uint64_t close();

private:
    void send(const void* data, std::size_t size);
    /// The child's next answer: "<word> <rest>"; throws `E` with the child's message on "error".
    std::string answer(bool starting);
    void reap();

    pid_t child_ = -1;
    int toChild_ = -1;
    int fromChild_ = -1;
    std::string pending_;  ///< what the child wrote after the last answer
};

}  // namespace sbsim::python
