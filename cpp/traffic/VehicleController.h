#pragma once

#include <string>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/Color.h"

namespace sbsim::traffic {

/// Commands and live queries for one vehicle, forwarded to libsumo::Vehicle. Effects and services
/// act on vehicles only through this class, so every SUMO command has one place to look — and the
/// per-step snapshot learns of max-speed changes here (change it through this class, not libsumo).
/// The methods are virtual so unit tests can stand a model vehicle in for SUMO's.
class SBSIM_API VehicleController {
public:
    explicit VehicleController(std::string id) : id_(std::move(id)) {}
    virtual ~VehicleController() = default;

    const std::string& id() const { return id_; }

    // Live values, asked of SUMO now (not the step's snapshot).
    virtual std::string typeId() const;
    virtual std::string roadId() const;
    virtual std::string laneId() const;
    virtual int laneIndex() const;
    virtual double speed() const;
    virtual double maxSpeed() const;
    virtual double emergencyDecel() const;
    virtual int speedMode() const;

    virtual void setMaxSpeed(double mps);
    /// Holds the vehicle at `mps`; a negative value hands speed control back to SUMO.
    virtual void setSpeed(double mps);
    /// Changes speed linearly to `mps` over `seconds`.
    virtual void slowDown(double mps, double seconds);
    virtual void setSpeedMode(int mode);
    virtual void changeLane(int laneIndex, double seconds);
    virtual void changeLaneRelative(int offset, double seconds);

    // Added after the others so that service modules built against the older class keep working.
    /// The factor on the lanes' speed limits the driver keeps to (SUMO's chosen speed factor).
    virtual double speedFactor() const;
    virtual Color color() const;
    virtual void setSpeedFactor(double factor);
    /// Gives the vehicle another type (its max speed becomes the type's).
    virtual void setType(const std::string& typeId);
    virtual void setColor(const Color& color);

private:
    std::string id_;
};

}  // namespace sbsim::traffic
