#include "sbsim/storyboard/effects/SpeedEffect.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbsim::storyboard {

SpeedEffect::SpeedEffect(double mps) : mps_(mps) {
    if (!std::isfinite(mps) || mps < 0) {
        throw std::invalid_argument(fmt::format("SpeedEffect needs a speed >= 0 in m/s, got {:f}", mps));
    }
}

std::string SpeedEffect::describe() const { return fmt::format("SpeedEffect({:g} m/s)", mps_); }

}  // namespace sbsim::storyboard
