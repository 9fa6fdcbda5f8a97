#include "sbsim/storyboard/effects/SetSpeedEffect.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace sbsim::storyboard {

SetSpeedEffect::SetSpeedEffect(double mps) : mps_(mps) {
    if (!std::isfinite(mps) || mps < 0) {
        throw std::invalid_argument(fmt::format("SetSpeedEffect needs a speed >= 0 in m/s, got {:f}", mps));
    }
}

std::string SetSpeedEffect::describe() const { return fmt::format("SetSpeedEffect({:g} m/s)", mps_); }

}  // namespace sbsim::storyboard
