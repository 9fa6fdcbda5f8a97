#pragma once

#include <string>
#include <string_view>

#include "sbsim/facilities/ActionId.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::facilities {

/// What happened to a DENM event at one station: a use case (at the originator) or the DENM
/// memory (at a receiver) started, updated or terminated it, or the memory dropped it expired.
enum class DenmPhase { New, Update, Terminate, Expired };

/// "new", "update", "terminate", "expired": the trace's words.
SBSIM_API std::string_view phaseName(DenmPhase phase);

/// One line of the DENM trace: {"t":…,"event":"denm","phase":…,"station":…,"action":…,"cause":…}.
struct SBSIM_API DenmPhaseEvent {
    kernel::SimTime time;
    DenmPhase phase = DenmPhase::New;
    std::string station;  ///< where it happened: the originator, or the receiver
    ActionId action;
    int cause = 0;
};

/// Where DENM phase events go (the app writes them to a trace); none by default.
class SBSIM_API DenmPhaseSink {
public:
    virtual ~DenmPhaseSink() = default;
    virtual void denmPhase(const DenmPhaseEvent& event) = 0;
};

}  // namespace sbsim::facilities
