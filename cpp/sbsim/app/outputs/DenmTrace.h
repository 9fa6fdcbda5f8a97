#pragma once

#include <ostream>

#include "sbsim/facilities/DenmPhase.h"

namespace sbsim::app {

/// Writes DENM phase events as JSON Lines: {"t":…,"event":"denm","phase":"new"|"update"|
/// "terminate"|"expired","station":…,"action":"<station>:<sequence>","cause":…}. `--denm-trace`
/// today; the line format is the message trace's, so the radio's --messages writer can take it.
class DenmTrace : public facilities::DenmPhaseSink {
public:
    explicit DenmTrace(std::ostream& out) : out_(out) {}
    void denmPhase(const facilities::DenmPhaseEvent& event) override;

private:
    std::ostream& out_;
};

}  // namespace sbsim::app
