#include "sbsim/storyboard/conditions/PolygonCondition.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

PolygonCondition::PolygonCondition(std::vector<Eigen::Vector2d> vertices) : polygon_(std::move(vertices)) {}

ConditionResult PolygonCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return polygon_.contains(ctx.snapshot().positions().col(ego));
}

std::string PolygonCondition::describe() const {
    std::vector<std::string> points;
    for (const auto& v : polygon_.vertices()) points.push_back(fmt::format("({:g}, {:g})", v.x(), v.y()));
    return fmt::format("PolygonCondition({} points, SUMO frame: {})", points.size(), fmt::join(points, " "));
}

std::optional<ConditionArea> PolygonCondition::area() const {
    return ConditionArea{polygon_.vertices(), std::nullopt, givenFrame_};
}

void PolygonCondition::check(CheckContext& ctx) const { ctx.warnOutsideNetwork(describe(), *area()); }

}  // namespace sbsim::storyboard
