#pragma once

#include <memory>
#include <string_view>

#include "sbsim/kernel/RandomStream.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/VehicleIdMap.h"

namespace sbsim::storyboard {

/// True for a vehicle with probability p, decided once at its first evaluation (one draw of the
/// stream, uniform01() < p) and kept while it runs.
class LikelihoodCondition : public Condition {
public:
    /// p is clamped to [0, 1]; throws std::invalid_argument for a null stream or a NaN p.
    LikelihoodCondition(std::shared_ptr<kernel::RandomStream> rng, double p);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void forget(std::string_view vehicleId) override;
    std::size_t heldVehicles() const override { return decisions_.size(); }

    std::string describe() const override;
    double probability() const { return p_; }

private:
    std::shared_ptr<kernel::RandomStream> rng_;
    double p_;
    VehicleIdMap<bool> decisions_;
};

}  // namespace sbsim::storyboard
