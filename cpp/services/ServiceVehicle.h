#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/VehicleRegistry.h"

namespace sbsim::services {

/// What one service commands its vehicle through (Service::vehicle()): the vehicle's one
/// controller, except that a max speed is this service's cap on the vehicle's effect stack. So a
/// service's cap and a story's compose like two stories' caps: the latest set rules, and the
/// vehicle's own max speed comes back only after the last one ended (endMaxSpeed(), or the
/// vehicle leaving). A service setting a cap again replaces its own.
class SBSIM_API ServiceVehicle : public traffic::VehicleController {
public:
    ServiceVehicle(std::shared_ptr<traffic::VehicleRegistry::Vehicle> vehicle, traffic::VehicleRegistry& registry);

    /// This service's cap on the vehicle's max speed, the latest of all caps from now on.
    void setMaxSpeed(double mps) override;
    /// Ends this service's cap (if any): the cap before it, or the vehicle's own max speed, rules again.
    void endMaxSpeed();

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
    void setVia(const std::vector<std::string>& edges) override { controller().setVia(edges); }
    void changeTarget(const std::string& edge) override { controller().changeTarget(edge); }

private:
    traffic::VehicleController& controller() const { return *vehicle_->controller; }

    std::shared_ptr<traffic::VehicleRegistry::Vehicle> vehicle_;
    traffic::VehicleRegistry& registry_;
    std::optional<traffic::EffectStack::Token> cap_;  // this service's cap on the stack
};

}  // namespace sbsim::services
