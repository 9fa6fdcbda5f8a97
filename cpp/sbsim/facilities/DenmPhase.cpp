#include "sbsim/facilities/DenmPhase.h"

namespace sbsim::facilities {

std::string_view phaseName(DenmPhase phase) {
    switch (phase) {
        case DenmPhase::New:
            return "new";
        case DenmPhase::Update:
            return "update";
        case DenmPhase::Terminate:
            return "terminate";
        case DenmPhase::Expired:
            return "expired";
    }
    return "?";
}

}  // namespace sbsim::facilities
