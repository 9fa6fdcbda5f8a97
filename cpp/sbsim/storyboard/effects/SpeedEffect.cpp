#include "sbsim/storyboard/effects/SpeedEffect.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbsim::storyboard {

SpeedEffect::SpeedEffect(double mps, double over) : mps_(mps), over_(over) {
    if (!std::isfinite(mps) || mps < 0) {
        throw std::invalid_argument(fmt::format("SpeedEffect needs a speed >= 0 in m/s, got {:f}", mps));
    }
    if (!std::isfinite(over) || over < 0) {
        throw std::invalid_argument(fmt::format("SpeedEffect over= needs seconds >= 0, got {:f}", over));
    }
}

std::string SpeedEffect::describe() const {
    if (over_ > 0) return fmt::format("SpeedEffect({:g} m/s, over {:g} s)", mps_, over_);
    return fmt::format("SpeedEffect({:g} m/s)", mps_);
}

}  // namespace sbsim::storyboard
