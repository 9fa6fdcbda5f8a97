#pragma once

#include <algorithm>
#include <map>
#include <memory>

#include "sbsim/traffic/EffectStack.h"

namespace sbsim::storyboard {

/// Whether each activation of a transition effect reached its target: the flag its transition on
/// the effect stack sets, kept per stack entry while the entry lives. An effect is complete once
/// every live activation reached its target (OpenSCENARIO's action end).
class ReachedFlags {
public:
    void track(traffic::EffectStack::Token token, std::shared_ptr<const bool> reached) {
        flags_[token] = std::move(reached);
    }
    void forget(traffic::EffectStack::Token token) { flags_.erase(token); }
    bool allReached() const {
        return std::all_of(flags_.begin(), flags_.end(), [](const auto& f) { return *f.second; });
    }

private:
    std::map<traffic::EffectStack::Token, std::shared_ptr<const bool>> flags_;
};

}  // namespace sbsim::storyboard
