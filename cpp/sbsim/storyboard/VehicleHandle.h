#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/VehicleController.h"

namespace sbsim::storyboard {

/// A vehicle used after it left the simulation, through a handle a script kept.
class SBSIM_API VehicleGone : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// What story code (Python effects) gets to command a vehicle: it may be kept past the call and
/// past the vehicle's life without harm. It refers to the storyboard's controller weakly; once the
/// vehicle has left, every use throws VehicleGone naming it. Arguments are checked before SUMO
/// sees them (std::invalid_argument): speeds finite and >= 0, durations finite and >= 0.
class SBSIM_API VehicleHandle {
public:
    VehicleHandle(std::string id, std::weak_ptr<traffic::VehicleController> controller)
        : id_(std::move(id)), controller_(std::move(controller)) {}

    const std::string& id() const { return id_; }
    /// Whether the vehicle is still in the simulation.
    bool alive() const { return !controller_.expired(); }

    std::string typeId() const { return get().typeId(); }
    std::string roadId() const { return get().roadId(); }
    std::string laneId() const { return get().laneId(); }
    int laneIndex() const { return get().laneIndex(); }
    double speed() const { return get().speed(); }
    double maxSpeed() const { return get().maxSpeed(); }
    int speedMode() const { return get().speedMode(); }

    void setMaxSpeed(double mps);
    /// A negative speed hands control back to SUMO, as in libsumo; NaN and infinities are refused.
    void setSpeed(double mps);
    void slowDown(double mps, double seconds);
    void setSpeedMode(int mode);
    void changeLane(int laneIndex, double seconds);

private:
    traffic::VehicleController& get() const;

    std::string id_;
    std::weak_ptr<traffic::VehicleController> controller_;
};

}  // namespace sbsim::storyboard
