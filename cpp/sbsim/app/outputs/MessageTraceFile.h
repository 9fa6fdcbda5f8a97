#pragma once

#include <cstdint>
#include <ostream>
#include <queue>
#include <string>
#include <vector>

#include "sbsim/facilities/DenmPhase.h"
#include "sbsim/radio/MessageTrace.h"

namespace sbsim::app {

/// The message trace (--messages): one JSON object per line, in time order: what the radio did
/// (tx, rx, lost) and what happened to DENM events (denm: a use case at the originator or a
/// receiver's DENM memory started, updated, terminated or dropped one). Lines that a medium reports
/// ahead of time (a disc-model reception after its latency) wait in a heap until the simulation
/// reaches their time; ties keep the order they were reported in.
class MessageTraceFile : public radio::MessageTrace, public facilities::DenmPhaseSink {
public:
    explicit MessageTraceFile(std::ostream& out) : out_(out) {}
    void record(const radio::TraceLine& line, kernel::SimTime now) override;
    /// {"t":…,"event":"denm","phase":"new"|"update"|"terminate"|"expired","station":…,
    /// "action":"<station>:<sequence>","cause":…}, at the event's time (now).
    void denmPhase(const facilities::DenmPhaseEvent& event) override;
    /// At the end of the run (at `end`): writes the lines still waiting up to `end` and drops
    /// those after it (receptions the run ended before).
    void finish(kernel::SimTime end);

    /// The line as written, without its newline.
    static std::string format(const radio::TraceLine& line);

private:
    struct Pending {
        kernel::SimTime t;
        std::uint64_t order;
        std::string text;
        bool operator>(const Pending& o) const { return t != o.t ? t > o.t : order > o.order; }
    };
    void writeUpTo(kernel::SimTime now);

    std::ostream& out_;
    std::priority_queue<Pending, std::vector<Pending>, std::greater<>> pending_;
    std::uint64_t order_ = 0;
};

}  // namespace sbsim::app
