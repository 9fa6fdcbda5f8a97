#pragma once

#include <string>

#include "traffic/VehicleSnapshot.h"

namespace sbsim::traffic {

/// Commands and live queries for one vehicle, forwarded to libsumo::Vehicle. Effects and services
/// act on vehicles only through this class, so every SUMO command has one place to look.
class VehicleController {
public:
    explicit VehicleController(std::string id) : id_(std::move(id)) {}

    const std::string& id() const { return id_; }

    // Live values, asked of SUMO now (not the step's snapshot).
    std::string typeId() const;
    std::string roadId() const;
    std::string laneId() const;
    int laneIndex() const;
    double speed() const;
    double maxSpeed() const;
    double emergencyDecel() const;
    int speedMode() const;

    void setMaxSpeed(double mps) const;
    /// Holds the vehicle at `mps`; a negative value hands speed control back to SUMO.
    void setSpeed(double mps) const;
    /// Changes speed linearly to `mps` over `seconds`.
    void slowDown(double mps, double seconds) const;
    void setSpeedMode(int mode) const;
    void changeLane(int laneIndex, double seconds) const;
    void changeLaneRelative(int offset, double seconds) const;

private:
    std::string id_;
};

}  // namespace sbsim::traffic
