#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/VehicleRegistry.h"

namespace sbsim::services {

/// What one service commands its vehicle through (Service::vehicle()): the vehicle's one
/// controller, except that a max speed and a route change are this service's entries on the
/// vehicle's effect stack. So a service's cap and a story's compose like two stories' caps: the
/// latest set rules, and the vehicle's own max speed comes back only after the last one ended
/// (endMaxSpeed(), or the vehicle leaving); likewise a service's target or via edges and a story's
/// RouteEffect (endRoute()). A service setting either again replaces its own entry. Lane changes
/// stay SUMO's own timed commands (changeLane's duration), not stack entries: a story's LaneEffect
/// renews its lane every step and so rules while it is active.
class SBSIM_API ServiceVehicle : public traffic::VehicleController {
public:
    ServiceVehicle(std::shared_ptr<traffic::VehicleRegistry::Vehicle> vehicle, traffic::VehicleRegistry& registry);

    /// This service's cap on the vehicle's max speed, the latest of all caps from now on.
    void setMaxSpeed(double mps) override;
    /// Ends this service's cap (if any): the cap before it, or the vehicle's own max speed, rules again.
    void endMaxSpeed();
    /// This service's route change: to `edge`, through the via edges it set (if any).
    void changeTarget(const std::string& edge) override;
    /// This service's route change: through `edges`, to the target it set (or the vehicle's own).
    void setVia(const std::vector<std::string>& edges) override;
    /// Ends this service's route change: the one before it, or the vehicle's own destination, rules again.
    void endRoute();
    /// This service's hold at standstill (a story's StopEffect's entry on the stack) and its end.
    void stop();
    void endStop();
    /// This service's speed factor and colour as entries on the effect stack (the latest of all
    /// rules; after endSpeedFactor() / endColor() the one before, or the vehicle's own, comes back),
    /// unlike setSpeedFactor() and setColor(), which command SUMO directly.
    void holdSpeedFactor(double factor);
    void endSpeedFactor();
    void holdColor(const traffic::Color& color);
    void endColor();

    std::string typeId() const override { return controller().typeId(); }
    std::string roadId() const override { return controller().roadId(); }
    std::string laneId() const override { return controller().laneId(); }
    int laneIndex() const override { return controller().laneIndex(); }
    double speed() const override { return controller().speed(); }
    double maxSpeed() const override { return controller().maxSpeed(); }
    double emergencyDecel() const override { return controller().emergencyDecel(); }
    int speedMode() const override { return controller().speedMode(); }
    void setSpeed(double mps) override { controller().setSpeed(mps); }
    void slowDown(double mps, double seconds) override { controller().slowDown(mps, seconds); }
    void setSpeedMode(int mode) override { controller().setSpeedMode(mode); }
    void changeLane(int laneIndex, double seconds) override { controller().changeLane(laneIndex, seconds); }
    void changeLaneRelative(int offset, double seconds) override { controller().changeLaneRelative(offset, seconds); }
    double speedFactor() const override { return controller().speedFactor(); }
    traffic::Color color() const override { return controller().color(); }
    void setSpeedFactor(double factor) override { controller().setSpeedFactor(factor); }
    void setType(const std::string& typeId) override { controller().setType(typeId); }
    void setColor(const traffic::Color& color) override { controller().setColor(color); }
    int laneCount() const override { return controller().laneCount(); }
    std::vector<std::string> route() const override { return controller().route(); }
    std::vector<std::string> via() const override { return controller().via(); }
    traffic::Position position() const override { return controller().position(); }
    std::optional<double> drivingDistance(const std::string& edge, double position) const override {
        return controller().drivingDistance(edge, position);
    }
    std::optional<double> drivingDistanceTo(double x, double y) const override {
        return controller().drivingDistanceTo(x, y);
    }

private:
    traffic::VehicleController& controller() const { return *vehicle_->controller; }
    /// Makes push(token) this service's entry in a domain, replacing its previous one (pushed first,
    /// so the vehicle's own value never shows in between).
    void replace(std::optional<traffic::EffectStack::Token>& own,
                 const std::function<void(traffic::EffectStack::Token)>& push);
    /// Removes this service's entry `own` (if any) from the stack.
    void end(std::optional<traffic::EffectStack::Token>& own);

    std::shared_ptr<traffic::VehicleRegistry::Vehicle> vehicle_;
    traffic::VehicleRegistry& registry_;
    std::optional<traffic::EffectStack::Token> cap_;    // this service's cap on the stack
    std::optional<traffic::EffectStack::Token> route_;  // this service's route change on the stack
    traffic::EffectStack::Route routeValue_;            // what it asked for so far
    std::optional<traffic::EffectStack::Token> hold_, factor_, color_;
};

}  // namespace sbsim::services
