#include "sbsim/storyboard/effects/LaneEffect.h"

#include <fmt/format.h>

#include <stdexcept>
#include <string>

namespace sbsim::storyboard {

LaneEffect::LaneEffect(int laneIndex) : laneIndex_(laneIndex) {
    if (laneIndex < 0)
        throw std::invalid_argument("LaneEffect: lane index must be >= 0, not " + std::to_string(laneIndex));
}

std::string LaneEffect::describe() const { return fmt::format("LaneEffect({})", laneIndex_); }

}  // namespace sbsim::storyboard
