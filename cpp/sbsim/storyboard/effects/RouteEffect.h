#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Routes the vehicle while the story is active: to `targetEdge` (SUMO's changeTarget), or to its
/// destination through `via` (SUMO's setVia), by travel time from where it is. At the end it is
/// routed from where it is then to the destination it had before. A route SUMO cannot find is a
/// warning; the vehicle keeps the route it has.
class RouteEffect : public Effect {
public:
    /// Throws std::invalid_argument unless exactly one of a target edge and a non-empty via list is
    /// given, or for an empty edge id.
    RouteEffect(std::optional<std::string> targetEdge, std::vector<std::string> via);
    std::string describe() const override;
    /// Warns about edges the network does not have.
    void check(CheckContext& ctx) const override;
    const traffic::EffectStack::Route& route() const { return route_; }
    void apply(EffectScope& scope) override { scope.stack().pushRoute(scope.token(), route_); }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }

private:
    traffic::EffectStack::Route route_;
};

}  // namespace sbsim::storyboard
