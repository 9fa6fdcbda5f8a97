#pragma once

#include <ostream>
#include <string>

#include "sbsim/app/outputs/TraceWriter.h"

namespace sbsim::app {

/// The message trace as JSON Lines: one object a line, its keys in a fixed order (t, event, type,
/// station, sender, seq, the event's own, then the message's trace fields); denm lines are
/// {"t","event":"denm","phase","station","action","cause"}. Its budget counts every byte exactly.
class JsonLinesTrace : public TraceWriter {
public:
    explicit JsonLinesTrace(std::ostream& out) : out_(out) {}
    bool write(const TraceRecord& line, std::uint64_t budget) override;
    std::uint64_t bytes() const override { return bytes_; }
    void finish() override { out_.flush(); }
    std::string_view format() const override { return "jsonl"; }

    /// The line as written, without its newline.
    static std::string format(const TraceRecord& line);

private:
    std::ostream& out_;
    std::uint64_t bytes_ = 0;
};

}  // namespace sbsim::app
