#pragma once

#include <string>

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Sends a StoryboardSignal with `cause` to the vehicle's services once, when the story activates.
class SignalEffect : public Effect {
public:
    explicit SignalEffect(std::string cause) : cause_(std::move(cause)) {}
    const std::string& cause() const { return cause_; }
    void apply(EffectScope& scope) override { scope.emitSignal(cause_); }
    void remove(EffectScope&) override {}

private:
    std::string cause_;
};

}  // namespace sbsim::storyboard
