#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "sbsim/app/outputs/TraceWriter.h"
#include "sbsim/python/ParquetStream.h"

namespace sbsim::app {

/// The message trace as Parquet (--messages FILE.parquet): the JSON Lines trace's fields as
/// columns (t in seconds; a field a line lacks is null), compressed, handed to pyarrow a row
/// group at a time as the run goes, so memory stays one row group whatever the run's length.
/// Columns: t, event, type, station, sender, seq, bytes, x, y, cbr, distance, delay, power_dbm,
/// sinr_db, reason, phase, action, cause, subcause (a DENM's), more, then the other trace fields
/// of messages, each a column of its own when seen before the first row group is written; a
/// field first seen later (or of another type than its column) goes to `more`, a JSON object.
///
/// The budget: a row group is written early when its raw columns would pass what is left of the
/// budget, and the trace is full once the file plus another row group like the last plus the
/// footer would pass it.
class ParquetTrace : public TraceWriter {
public:
    static constexpr std::size_t kRowsPerGroup = 65536;

    /// `what` starts error messages ("--messages: cannot write 'x.parquet'").
    ParquetTrace(std::unique_ptr<python::ParquetStream> stream, std::string what);
    bool write(const TraceRecord& line, std::uint64_t budget) override;
    std::uint64_t bytes() const override { return fileBytes_; }
    void finish() override;
    std::string_view format() const override { return "parquet"; }

private:
    using Type = python::ParquetColumn::Type;
    std::size_t column(const std::string& name, Type type);
    void append(const TraceRecord& line);
    void flush();
    std::uint64_t footerReserve() const;
    std::size_t rawBytes() const;

    std::unique_ptr<python::ParquetStream> stream_;
    std::string what_;
    std::vector<python::ParquetColumn> columns_;
    std::unordered_map<std::string, std::size_t> byName_;
    std::vector<char> set_;  ///< per column: has a value in the row being appended
    std::size_t rows_ = 0;
    std::size_t groups_ = 0;
    std::uint64_t fileBytes_ = 0;
    std::uint64_t lastGroupBytes_ = 0;
    bool full_ = false;
    bool finished_ = false;
};

}  // namespace sbsim::app
