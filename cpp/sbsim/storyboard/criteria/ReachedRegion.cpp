#include "sbsim/storyboard/criteria/ReachedRegion.h"

#include <fmt/format.h>

namespace sbsim::storyboard {

ReachedRegion::ReachedRegion(std::string vehicle, geometry::Polygon area, kernel::SimTime by)
    : vehicle_(std::move(vehicle)), area_(std::move(area)), by_(by) {}

std::string ReachedRegion::describe() const {
    return fmt::format("ReachedRegion({}, {} points, by={} s)", vehicle_, area_.vertices().size(), by_.str());
}

void ReachedRegion::observe(const EvaluationContext& ctx) {
    if (reached_) return;
    const auto i = ctx.snapshot().indexOf(vehicle_);
    if (!i) return;
    seen_ = true;
    if (area_.contains(ctx.snapshot().positions().col(*i))) reached_ = ctx.now();
}

CriterionVerdict ReachedRegion::verdict(const CriterionRun& /*run*/) const {
    const std::string expected = fmt::format("in the area by t={} s", by_.str());
    if (reached_) return {*reached_ <= by_, fmt::format("reached at t={} s", reached_->str()), expected};
    return {false, seen_ ? "never reached" : fmt::format("no vehicle {} seen", vehicle_), expected};
}

}  // namespace sbsim::storyboard
