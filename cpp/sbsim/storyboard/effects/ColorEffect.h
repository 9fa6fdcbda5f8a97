#pragma once

#include "sbsim/storyboard/Effect.h"
#include "sbsim/traffic/Color.h"

namespace sbsim::storyboard {

/// Paints the vehicle (SUMO's setColor, seen in sumo-gui) while the story is active; its own
/// colour comes back at the end.
class ColorEffect : public Effect {
public:
    explicit ColorEffect(traffic::Color color) : color_(color) {}
    const traffic::Color& color() const { return color_; }
    void apply(EffectScope& scope) override { scope.stack().pushColor(scope.token(), color_); }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }

private:
    traffic::Color color_;
};

}  // namespace sbsim::storyboard
