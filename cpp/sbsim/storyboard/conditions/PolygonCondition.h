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
    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Position}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    const geometry::Polygon& polygon() const { return polygon_; }
    std::string describe() const override;
    std::optional<ConditionArea> area() const override;
    /// Warns when the polygon misses the network, naming the frame it would fit in.
    void check(CheckContext& ctx) const override;

    bool pure() const override { return true; }

    /// The frame the script wrote the points in (they are stored in SUMO's), so that `sbsim check`
    /// can say which frame would have fitted a polygon that misses the network.
    using GivenFrame = storyboard::GivenFrame;
    GivenFrame givenFrame() const { return givenFrame_; }
    void setGivenFrame(GivenFrame frame) { givenFrame_ = frame; }

private:
    geometry::Polygon polygon_;
    GivenFrame givenFrame_ = GivenFrame::Sumo;
};

}  // namespace sbsim::storyboard
