#pragma once

#include <functional>
#include <memory>
#include <string>
#include <unordered_map>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/EffectStack.h"
#include "sbsim/traffic/VehicleController.h"

namespace sbsim::traffic {

class SumoBridge;

/// The one command owner per vehicle: the storyboard and the services middleware both act on a
/// vehicle through the controller and effect stack handed out here, so a service's speed cap and
/// a story's compose on one stack instead of undoing each other. The program makes one and gives
/// it to both; an entry lives while someone holds it, and is handed out anew after drop().
class SBSIM_API VehicleRegistry {
public:
    struct Vehicle {
        Vehicle(std::unique_ptr<VehicleController> c, EffectStack::Warn warn)
            : controller(std::move(c)), stack(*controller, std::move(warn)) {}
        std::unique_ptr<VehicleController> controller;
        EffectStack stack;
    };
    using ControllerFactory = std::function<std::unique_ptr<VehicleController>(const std::string& id)>;

    /// Controllers command libsumo, without telling any snapshot of max-speed changes until attach().
    VehicleRegistry();

    /// Controllers tell `sumo`'s snapshot of max-speed changes, and commands SUMO refused count
    /// with its warnings (entries made from now on).
    void attach(SumoBridge& sumo);
    /// Replaces how vehicles are commanded (tests stand model vehicles in).
    void setControllerFactory(ControllerFactory factory) { makeController_ = std::move(factory); }

    /// `id`'s entry, made on first use.
    std::shared_ptr<Vehicle> of(const std::string& id);
    /// The vehicle left: holders keep what they hold, the next of() makes a new entry.
    void drop(const std::string& id) { vehicles_.erase(id); }
    /// Identifies one effect activation, unique across all of the vehicle's commanders.
    EffectStack::Token newToken() { return nextToken_++; }
    std::size_t size() const { return vehicles_.size(); }

private:
    ControllerFactory makeController_;
    EffectStack::Warn warn_;
    std::unordered_map<std::string, std::shared_ptr<Vehicle>> vehicles_;
    EffectStack::Token nextToken_ = 1;
};

}  // namespace sbsim::traffic
