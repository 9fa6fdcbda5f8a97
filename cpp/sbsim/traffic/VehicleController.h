#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/Color.h"
#include "sbsim/traffic/Position.h"

namespace sbsim::traffic {

/// SUMO refused a command that may fail in a running scenario (no route to an edge): one line,
/// SUMO's message. The caller decides whether the run goes on.
class SBSIM_API CommandRefused : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Told when a command changed a vehicle's max speed: the per-step snapshot reads max speeds
/// only then.
class SBSIM_API MaxSpeedListener {
public:
    virtual void maxSpeedChanged(const std::string& id) = 0;

protected:
    ~MaxSpeedListener() = default;
};

/// Commands and live queries for one vehicle, forwarded to libsumo::Vehicle. Effects and services
/// act on vehicles only through this class, so every SUMO command has one place to look — and the
/// per-step snapshot (`listener`) learns of max-speed changes here (change it through this class,
/// not libsumo). One vehicle has one controller: traffic::VehicleRegistry hands it out.
/// The methods are virtual so unit tests can stand a model vehicle in for SUMO's.
class SBSIM_API VehicleController {
public:
    explicit VehicleController(std::string id, MaxSpeedListener* listener = nullptr)
        : id_(std::move(id)), listener_(listener) {}
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

    // Added after the others, for the same reason.
    /// Lanes of the road the vehicle is on.
    virtual int laneCount() const;
    /// The edges of the vehicle's route, from its start to its destination.
    virtual std::vector<std::string> route() const;
    /// The edges its routings must pass, in order (SUMO's via).
    virtual std::vector<std::string> via() const;
    /// Makes the vehicle's next routings pass `edges` in order; throws CommandRefused for an
    /// unknown edge.
    virtual void setVia(const std::vector<std::string>& edges);
    /// Routes the vehicle from where it is to `edge` (through its via edges) by travel time; throws
    /// CommandRefused when SUMO finds no route, leaving the route as it was.
    virtual void changeTarget(const std::string& edge);

    // Added after the others, for the same reason.
    /// Where the vehicle is (front bumper), SUMO network frame.
    virtual Position position() const;
    /// The distance (m) the vehicle drives along its route to `position` m on `edge` (lane 0), or
    /// none when that spot is not on its route ahead (SUMO's getDrivingDistance).
    virtual std::optional<double> drivingDistance(const std::string& edge, double position) const;
    /// The distance (m) it drives along its route to the route's point nearest to (x, y), or none
    /// when the route does not pass there (SUMO's getDrivingDistance2D).
    virtual std::optional<double> drivingDistanceTo(double x, double y) const;

    // Added after the others, for the same reason: what OpenSCENARIO-grade transitions ask.
    /// SUMO's step length (s).
    virtual double stepLength() const;
    /// The distance (m) the vehicle drove since it departed (SUMO's odometer).
    virtual double odometer() const;
    /// Its centre's lateral offset (m) from its lane's centre, positive to the left.
    virtual double lateralLanePosition() const;
    /// The widths (m) of the lanes of the road it is on, from the right.
    virtual std::vector<double> laneWidths() const;
    /// Whether SUMO runs its sublane model (--lateral-resolution), which changeSublane needs.
    virtual bool sublaneModel() const;
    /// Moves the vehicle `latDist` m to the left (negative: right) within its road, in the next step.
    virtual void changeSublane(double latDist);
    virtual int laneChangeMode() const;
    virtual void setLaneChangeMode(int mode);
    virtual double maxSpeedLat() const;
    virtual void setMaxSpeedLat(double mps);
    /// A parameter of the vehicle (e.g. "laneChangeModel.lcAccelLat").
    virtual std::string parameter(const std::string& key) const;
    virtual void setParameter(const std::string& key, const std::string& value);

    // Added after the others, for the same reason: OpenSCENARIO's TeleportAction and RoutingAction.
    /// Its front bumper's distance (m) from the start of its lane.
    virtual double lanePosition() const;
    /// Puts the vehicle at `position` m on lane `laneId` now (SUMO's moveTo, a teleport); the lane's
    /// edge must be on its route, ahead or behind. Throws CommandRefused when SUMO refuses.
    virtual void moveTo(const std::string& laneId, double position);
    /// Replaces its route by `edges`, the first of which is the edge it is on; throws
    /// CommandRefused for a route SUMO refuses (not connected, not starting there).
    virtual void setRoute(const std::vector<std::string>& edges);

private:
    std::string id_;
    MaxSpeedListener* listener_;
};

}  // namespace sbsim::traffic
