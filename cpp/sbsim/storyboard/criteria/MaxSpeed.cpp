#include "sbsim/storyboard/criteria/MaxSpeed.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace sbsim::storyboard {

MaxSpeed::MaxSpeed(double mps, VehicleSet vehicles) : limit_(mps), vehicles_(std::move(vehicles)) {
    if (!std::isfinite(mps) || mps < 0) throw std::invalid_argument(fmt::format("MaxSpeed: {} m/s is no limit", mps));
}

std::string MaxSpeed::describe() const {
    const std::string more = vehicles_.argument();
    return fmt::format("MaxSpeed({:g}{}{})", limit_, more.empty() ? "" : ", ", more);
}

void MaxSpeed::observe(const EvaluationContext& ctx) {
    const traffic::VehicleSnapshot& s = ctx.snapshot();
    for (traffic::VehicleSnapshot::Index i = 0; i < s.size(); ++i) {
        // Strictly faster: the first vehicle at the top speed (in id order) is the one named.
        if (s.speeds()[i] > fastest_ && vehicles_.admits(ctx, s.ids()[i])) {
            fastest_ = s.speeds()[i];
            who_ = s.ids()[i];
            when_ = ctx.now();
        }
    }
}

CriterionVerdict MaxSpeed::verdict(const CriterionRun& /*run*/) const {
    const std::string expected = fmt::format("<= {:g} m/s", limit_);
    if (fastest_ < 0) return {true, "no vehicle seen", expected};
    // A margin for SUMO's rounding of speeds to its output precision.
    return {fastest_ <= limit_ + 1e-9, fmt::format("{:.3f} m/s ({} at t={} s)", fastest_, who_, when_.str()), expected};
}

}  // namespace sbsim::storyboard
