#pragma once

#include <cstdint>
#include <string>

#include "sbsim/storyboard/Effect.h"
#include "sbsim/traffic/Color.h"

namespace sbsim::storyboard {

/// Paints the vehicle (SUMO's setColor, seen in sumo-gui) while the story is active; its own
/// colour comes back at the end.
class ColorEffect : public Effect {
public:
    explicit ColorEffect(traffic::Color color) : color_(color) {}
    const traffic::Color& color() const { return color_; }
    std::string describe() const override {
        const auto n = [](std::uint8_t v) { return std::to_string(v); };
        const std::string alpha = color_.a == 255 ? "" : ", " + n(color_.a);
        return "ColorEffect(" + n(color_.r) + ", " + n(color_.g) + ", " + n(color_.b) + alpha + ")";
    }
    std::optional<std::string> domain() const override { return "colour"; }
    void apply(EffectScope& scope) override { scope.stack().pushColor(scope.token(), color_); }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }

private:
    traffic::Color color_;
};

}  // namespace sbsim::storyboard
