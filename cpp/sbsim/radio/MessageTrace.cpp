#include "sbsim/radio/MessageTrace.h"

namespace sbsim::radio {

std::string_view lossReasonName(LossReason reason) {
    switch (reason) {
        case LossReason::Sensing:
            return "sensing";
        case LossReason::Propagation:
            return "propagation";
        case LossReason::Collision:
            return "collision";
        case LossReason::HalfDuplex:
            return "half-duplex";
        case LossReason::Queue:
            return "queue";
        case LossReason::Range:
            return "range";
        case LossReason::Fade:
            break;
    }
    return "fade";
}

}  // namespace sbsim::radio
