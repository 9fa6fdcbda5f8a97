#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/NetworkStack.h"
#include "sbsim/storyboard/TypeName.h"
#include "sbsim/traffic/NetworkController.h"

namespace sbsim::storyboard {

class CheckContext;
class Story;

/// What a world effect may act on when its WorldStory activates or deactivates.
class SBSIM_API WorldScope {
public:
    virtual ~WorldScope() = default;
    virtual const Story& story() const = 0;
    virtual kernel::SimTime now() const = 0;
    virtual traffic::NetworkController& network() = 0;
    /// The network's composition of world effects (closures, held signals).
    virtual NetworkStack& stack() = 0;
    /// Identifies this activation of this effect (for NetworkStack::remove).
    virtual NetworkStack::Token token() const = 0;
};

/// An effect on the network rather than on one vehicle (a WorldStory's): apply() when the story
/// activates, remove() when its condition turns false. Kept apart from Effect so a story cannot
/// mix them up: a Story takes Effects, a WorldStory WorldEffects.
class SBSIM_API WorldEffect {
public:
    virtual ~WorldEffect() = default;
    virtual void apply(WorldScope& scope) = 0;
    virtual void remove(WorldScope& scope) = 0;
    /// The class name messages show.
    virtual std::string typeName() const { return typeNameOf(typeid(*this)); }
    /// This effect in one line, as `sbsim check` prints it: its class name and arguments.
    virtual std::string describe() const { return typeName(); }
    /// The vehicle ids this effect adds to the simulation (as defined as the route files' ones).
    virtual std::vector<std::string> definedVehicles() const { return {}; }
    /// Reports to `sbsim check` what looks wrong in this effect (an id the network lacks).
    virtual void check(CheckContext& /*ctx*/) const {}
};

using WorldEffectPtr = std::shared_ptr<WorldEffect>;

}  // namespace sbsim::storyboard
