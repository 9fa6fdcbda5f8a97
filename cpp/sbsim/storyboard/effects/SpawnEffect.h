#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// Adds one vehicle when the story activates (it departs at the next step); removing the effect
/// does nothing. The route is given edge by edge, or found from one edge to another (the fastest
/// for the type, around closed edges). Depart lane, position and speed are SUMO's strings; unset
/// ones take SUMO's defaults ("first", "base", "0").
class SpawnEffect : public WorldEffect {
public:
    struct Spec {
        std::string id;
        std::vector<std::string> route;  ///< empty: from `from` to `to`
        std::string from, to;
        std::optional<std::string> type, lane, position, speed;
    };
    /// Throws std::invalid_argument for an empty id, or neither a route nor both from and to (or both).
    explicit SpawnEffect(Spec spec);
    std::string describe() const override;
    std::vector<std::string> definedVehicles() const override { return {spec_.id}; }
    /// Warns about edges and a type SUMO does not know.
    void check(CheckContext& ctx) const override;
    const Spec& spec() const { return spec_; }
    /// Throws std::invalid_argument if the vehicle exists, an edge is unknown or no route is found.
    void apply(WorldScope& scope) override;
    void remove(WorldScope& /*scope*/) override {}

private:
    Spec spec_;
};

}  // namespace sbsim::storyboard
