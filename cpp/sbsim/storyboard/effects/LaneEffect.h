#pragma once

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Keeps the vehicle to lane `laneIndex` (0: the rightmost) while the story is active (SUMO's
/// changeLane, renewed each step); on a road with fewer lanes, to its leftmost. At the end the
/// vehicle changes lanes as it likes again.
class LaneEffect : public Effect {
public:
    /// Throws std::invalid_argument for a negative index.
    explicit LaneEffect(int laneIndex);
    std::string describe() const override;
    int laneIndex() const { return laneIndex_; }
    void apply(EffectScope& scope) override { scope.stack().pushLane(scope.token(), laneIndex_); }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }

private:
    int laneIndex_;
};

}  // namespace sbsim::storyboard
