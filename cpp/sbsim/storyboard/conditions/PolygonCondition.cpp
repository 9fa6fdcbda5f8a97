#include "sbsim/storyboard/conditions/PolygonCondition.h"

namespace sbsim::storyboard {

PolygonCondition::PolygonCondition(std::vector<Eigen::Vector2d> vertices) : polygon_(std::move(vertices)) {}

ConditionResult PolygonCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return polygon_.contains(ctx.snapshot().positions().col(ego));
}

}  // namespace sbsim::storyboard
