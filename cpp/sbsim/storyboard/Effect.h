#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/ConditionResult.h"
#include "sbsim/storyboard/TypeName.h"
#include "sbsim/storyboard/VehicleHandle.h"
#include "sbsim/traffic/EffectStack.h"
#include "sbsim/traffic/VehicleController.h"

namespace sbsim::storyboard {

class CheckContext;
class Story;

/// What an effect may act on when its story activates or deactivates for one vehicle.
class SBSIM_API EffectScope {
public:
    virtual ~EffectScope() = default;
    virtual const Story& story() const = 0;
    virtual const std::string& vehicleId() const = 0;
    virtual traffic::VehicleController& vehicle() = 0;
    /// A handle to the vehicle that may outlive the call (what scripts get).
    virtual VehicleHandle handle() = 0;
    /// The vehicle's composition of built-in effects.
    virtual traffic::EffectStack& stack() = 0;
    /// Identifies this activation of this effect (for traffic::EffectStack::remove).
    virtual traffic::EffectStack::Token token() const = 0;
    /// The condition's other vehicles at activation, ascending ids.
    virtual const std::vector<std::string>& others() const = 0;
    /// Emits a StoryboardSignal for this vehicle (and logs it); `onExit` when the story deactivates.
    virtual void emitSignal(const std::string& cause, bool onExit = false) = 0;
    /// Another vehicle's controller, for effects that follow it (a speed relative to its speed);
    /// its live queries throw while it does not run.
    virtual std::shared_ptr<traffic::VehicleController> controllerOf(const std::string& id) = 0;
};

/// An effect of a story (Artery's EffectFactory role): apply() when the story activates for a
/// vehicle, remove() when it deactivates because its condition turned false. When a vehicle
/// leaves the simulation only vehicleLeft() is called: there is nothing left to command.
class SBSIM_API Effect {
public:
    virtual ~Effect() = default;
    virtual void apply(EffectScope& scope) = 0;
    virtual void remove(EffectScope& scope) = 0;
    /// The class name messages show (a Python effect: its Python class's).
    virtual std::string typeName() const { return typeNameOf(typeid(*this)); }
    /// This effect in one line, as `sbsim check` prints it: its class name and arguments.
    virtual std::string describe() const { return typeName(); }
    /// What the effect commands, if another effect of the same story could fight it over that
    /// ("speed"): `sbsim check` warns about two in one story.
    virtual std::optional<std::string> domain() const { return std::nullopt; }
    /// Reports to `sbsim check` what looks wrong in this effect (an id the network lacks).
    virtual void check(CheckContext& /*ctx*/) const {}
    /// As an OpenSCENARIO action (ScenarioMachine::addAction): whether it has done what it does on
    /// every vehicle it is applied to, so that its event may end. A one-shot effect is complete
    /// once applied; a transition when it reached its target; a continuous one never.
    virtual bool complete() const { return true; }
    /// The vehicle of activation `token` (`scope` as at its apply) left the simulation while the
    /// story was active: no command may go to it. An effect that keeps state per activation
    /// forgets it here (a transition that never reaches its target must not hold its event open).
    virtual void vehicleLeft(traffic::EffectStack::Token /*token*/) {}
};

using EffectPtr = std::shared_ptr<Effect>;

}  // namespace sbsim::storyboard
