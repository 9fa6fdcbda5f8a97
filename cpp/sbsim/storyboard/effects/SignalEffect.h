#pragma once

#include <optional>
#include <string>

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Sends a StoryboardSignal with `cause` to the vehicle's services once, when the story activates,
/// and with `onExit` (if given) once more when the story deactivates because its condition turned
/// false (not when the vehicle left: there is nobody left to tell).
class SignalEffect : public Effect {
public:
    explicit SignalEffect(std::string cause, std::optional<std::string> onExit = std::nullopt)
        : cause_(std::move(cause)), onExit_(std::move(onExit)) {}
    const std::string& cause() const { return cause_; }
    std::string describe() const override {
        return "SignalEffect('" + cause_ + "'" + (onExit_ ? ", on exit '" + *onExit_ + "'" : "") + ")";
    }
    const std::optional<std::string>& onExit() const { return onExit_; }
    void apply(EffectScope& scope) override { scope.emitSignal(cause_); }
    void remove(EffectScope& scope) override {
        if (onExit_) scope.emitSignal(*onExit_, true);
    }

private:
    std::string cause_;
    std::optional<std::string> onExit_;
};

}  // namespace sbsim::storyboard
