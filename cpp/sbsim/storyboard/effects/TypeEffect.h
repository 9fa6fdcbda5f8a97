#pragma once

#include <string>

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Gives the vehicle another vehicle type (SUMO's setType) while the story is active; the type it
/// had comes back at the end. The type must be known to SUMO (a route or additional file).
class TypeEffect : public Effect {
public:
    /// Throws std::invalid_argument for an empty id.
    explicit TypeEffect(std::string typeId);
    std::string describe() const override;
    std::optional<std::string> domain() const override { return "type"; }
    /// Warns about a type SUMO does not know.
    void check(CheckContext& ctx) const override;
    const std::string& typeId() const { return typeId_; }
    void apply(EffectScope& scope) override { scope.stack().pushType(scope.token(), typeId_); }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }

private:
    std::string typeId_;
};

}  // namespace sbsim::storyboard
