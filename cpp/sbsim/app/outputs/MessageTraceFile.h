#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "sbsim/app/outputs/MessageTraceFilter.h"
#include "sbsim/app/outputs/TraceRecord.h"
#include "sbsim/app/outputs/TraceWriter.h"
#include "sbsim/facilities/DenmPhase.h"
#include "sbsim/radio/MessageTrace.h"

namespace sbsim::app {

/// What the summary says of the message trace.
struct TraceFigures {
    std::string_view format;                     ///< "jsonl" or "parquet"
    std::uint64_t lines = 0;                     ///< written
    std::uint64_t bytes = 0;                     ///< the file's size
    std::uint64_t maxBytes = 0;                  ///< the budget
    std::optional<kernel::SimTime> truncatedAt;  ///< the first line the budget left out
};

/// The message trace (--messages), in time order: what the radio did (tx, rx, lost) and what
/// happened to DENM events (denm: a use case at the originator or a receiver's DENM memory
/// started, updated, terminated or dropped one), the lines the filter keeps, written by a
/// TraceWriter (JSON Lines or Parquet). Lines that a medium reports ahead of time (a disc-model
/// reception after its latency) wait in a heap until the simulation reaches their time; ties keep
/// the order they were reported in.
///
/// A budget bounds the file: the first line that would pass it ends the trace (the run goes on);
/// a warning on stderr says so once, and figures() keeps its time for the summary.
class MessageTraceFile : public radio::MessageTrace, public facilities::DenmPhaseSink {
public:
    MessageTraceFile(std::unique_ptr<TraceWriter> writer, MessageTraceFilter filter, std::uint64_t maxBytes);
    void record(const radio::TraceLine& line, kernel::SimTime now) override;
    /// {"t":…,"event":"denm","phase":"new"|"update"|"terminate"|"expired","station":…,
    /// "action":"<station>:<sequence>","cause":…}, at the event's time (now).
    void denmPhase(const facilities::DenmPhaseEvent& event) override;
    /// {"t":…,"event":"dcc","station":…,"state":"relaxed"|"active1"…"active5"|"restrictive",
    /// "cbr":…,"interval":…}: a station's DCC state changed (channel model), at now.
    void dccChanged(const radio::DccChange& change) override;
    /// At the end of the run (at `end`): writes the lines still waiting up to `end`, drops those
    /// after it (receptions the run ended before) and closes the format.
    void finish(kernel::SimTime end);

    /// The budget is spent: nothing more is written (the medium need not report any more).
    bool full() const { return truncatedAt_.has_value(); }
    TraceFigures figures() const;
    const MessageTraceFilter& filter() const { return filter_; }

private:
    // The record behind a pointer: the heap moves entries about, and a record is large.
    struct Pending {
        kernel::SimTime t;
        std::uint64_t order;
        std::unique_ptr<TraceRecord> record;
        bool operator>(const Pending& o) const { return t != o.t ? t > o.t : order > o.order; }
    };
    void writeUpTo(kernel::SimTime now);
    void emit(const TraceRecord& record);

    std::unique_ptr<TraceWriter> writer_;
    MessageTraceFilter filter_;
    std::uint64_t maxBytes_;
    std::priority_queue<Pending, std::vector<Pending>, std::greater<>> pending_;
    std::uint64_t order_ = 0;
    std::uint64_t lines_ = 0;
    std::optional<kernel::SimTime> truncatedAt_;
};

}  // namespace sbsim::app
