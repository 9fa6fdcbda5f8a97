#pragma once

#include <Eigen/Core>
#include <vector>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/geometry/Polygon.h"

namespace sbsim::storyboard {

/// True if the ego's position (SUMO network coordinates, front bumper centre) lies strictly inside
/// the polygon; the boundary is outside.
class PolygonCondition : public Condition {
public:
    /// Throws std::invalid_argument for fewer than 3 vertices.
    explicit PolygonCondition(std::vector<Eigen::Vector2d> vertices);
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    const geometry::Polygon& polygon() const { return polygon_; }

    bool pure() const override { return true; }

private:
    geometry::Polygon polygon_;
};

}  // namespace sbsim::storyboard
