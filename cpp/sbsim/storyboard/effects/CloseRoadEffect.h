#pragma once

#include <string>
#include <vector>

#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// Closes edges to every vehicle class while the story is active and steers traffic around them
/// (see NetworkStack for who is re-routed, and what happens to those that cannot avoid them). Two
/// closures of one edge compose: it opens when the last ends, with its lanes' permissions as before.
class CloseRoadEffect : public WorldEffect {
public:
    /// Throws std::invalid_argument for no edges or an empty edge id.
    explicit CloseRoadEffect(std::vector<std::string> edges);
    std::string describe() const override;
    /// Warns about edges the network does not have.
    void check(CheckContext& ctx) const override;
    const std::vector<std::string>& edges() const { return edges_; }
    void apply(WorldScope& scope) override { scope.stack().pushClosure(scope.token(), edges_); }
    void remove(WorldScope& scope) override { scope.stack().remove(scope.token()); }

private:
    std::vector<std::string> edges_;
};

}  // namespace sbsim::storyboard
