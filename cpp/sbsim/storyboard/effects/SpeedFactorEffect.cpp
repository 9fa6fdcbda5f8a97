#include "sbsim/storyboard/effects/SpeedFactorEffect.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbsim::storyboard {

SpeedFactorEffect::SpeedFactorEffect(double factor) : factor_(factor) {
    if (!std::isfinite(factor) || factor <= 0)
        throw std::invalid_argument("SpeedFactorEffect: factor must be > 0, not " + std::to_string(factor));
}

std::string SpeedFactorEffect::describe() const { return fmt::format("SpeedFactorEffect({:g})", factor_); }

}  // namespace sbsim::storyboard
