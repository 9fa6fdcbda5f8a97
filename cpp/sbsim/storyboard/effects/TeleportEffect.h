#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Puts the vehicle somewhere else at once (OpenSCENARIO's TeleportAction in an event): at
/// `position` m on lane `lane` of `edge`, or — relative to vehicle `relativeTo` as it is at
/// activation — `lane` lanes to the left of its lane on its edge and `position` m ahead of it
/// (RelativeLanePosition's dLane and ds). The vehicle keeps its speed.
///
/// SUMO moves a vehicle only along its route (moveTo): a target edge off the route is first made
/// part of it by routing there from where the vehicle is (changeTarget), and after that move the
/// vehicle drives on along `onward` (edges from the target edge, e.g. the road it follows) when
/// given, else to the destination it had; a target on its route keeps the route. No route there is
/// an error of the story (exit code 2).
/// Instantaneous: complete() at once; nothing to undo when the story ends.
class TeleportEffect : public Effect {
public:
    struct Target {
        std::string edge;  ///< empty for a relative target
        int lane = 0;      ///< index from the right; relative: lanes to the left
        double position = 0;
        std::optional<std::string> relativeTo;
    };
    /// Throws std::invalid_argument for an empty edge (absolute) or vehicle id (relative), a
    /// negative absolute lane or position, or a non-finite position.
    TeleportEffect(Target target, std::vector<std::string> onward = {});
    std::string describe() const override;
    void apply(EffectScope& scope) override;
    void remove(EffectScope& /*scope*/) override {}
    void check(CheckContext& ctx) const override;
    const Target& target() const { return target_; }
    const std::vector<std::string>& onward() const { return onward_; }

private:
    Target target_;
    std::vector<std::string> onward_;
};

}  // namespace sbsim::storyboard
