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
///
/// Kept (`keep`, OpenSCENARIO's RoutingAction in an event): the vehicle is routed once, at
/// activation, through `via` (edges it stands on dropped) to `targetEdge` (default: its own
/// destination), and keeps that route when the story ends; instantaneous (complete() at once). A
/// route SUMO cannot find is then an error of the story (exit code 2), not a warning.
class RouteEffect : public Effect {
public:
    /// Throws std::invalid_argument unless exactly one of a target edge and a non-empty via list is
    /// given (kept: at least one of them), or for an empty edge id.
    RouteEffect(std::optional<std::string> targetEdge, std::vector<std::string> via, bool keep = false);
    std::string describe() const override;
    /// Warns about edges the network does not have.
    void check(CheckContext& ctx) const override;
    const traffic::EffectStack::Route& route() const { return route_; }
    bool keep() const { return keep_; }
    void apply(EffectScope& scope) override;
    void remove(EffectScope& scope) override {
        if (!keep_) scope.stack().remove(scope.token());
    }

private:
    traffic::EffectStack::Route route_;
    bool keep_;
};

}  // namespace sbsim::storyboard
