#pragma once

#include <cstdint>
#include <string_view>

#include "sbsim/app/outputs/TraceRecord.h"

namespace sbsim::app {

/// How the message trace's lines go to its file: one format (JSON Lines, Parquet).
class TraceWriter {
public:
    virtual ~TraceWriter() = default;
    /// Writes the line, in time order, unless the file would then pass `budget` bytes: false,
    /// nothing written, and the trace is full (every later call says so too).
    virtual bool write(const TraceRecord& line, std::uint64_t budget) = 0;
    /// The file's size so far (what is written, or for Parquet handed to the file's writer).
    virtual std::uint64_t bytes() const = 0;
    /// At the end: writes what is still held and closes the format (Parquet's footer).
    virtual void finish() = 0;
    /// "jsonl" or "parquet".
    virtual std::string_view format() const = 0;
};

}  // namespace sbsim::app
