#pragma once

#include <memory>
#include <optional>
#include <string>

#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// True for a vehicle whose local dynamic map knows, from CAMs, at least one station whose last
/// CAM put it within `distance` m of the vehicle (any distance if none) and is at most `maxAge`
/// old (within the LDM's 1.1 s lifetime if none). Yields those stations that are running vehicles;
/// when none is (roadside units), plainly true. Reads the vehicle's position.
class CamCondition : public Condition {
public:
    CamCondition(std::optional<double> distance, std::optional<kernel::SimTime> maxAge);

    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    traffic::SnapshotColumns columns() const override { return traffic::SnapshotColumns::Position; }
    bool pure() const override { return true; }
    /// "CamCondition(within 50 m, max age 0.5 s)".
    std::string describe() const override;

private:
    std::optional<double> distance_;
    std::optional<kernel::SimTime> maxAge_;
};

}  // namespace sbsim::storyboard
