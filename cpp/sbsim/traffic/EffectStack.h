#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/traffic/Color.h"
#include "sbsim/traffic/LateralTransition.h"
#include "sbsim/traffic/LatestWins.h"
#include "sbsim/traffic/SpeedTransition.h"
#include "sbsim/traffic/VehicleController.h"

namespace sbsim::traffic {

/// One vehicle's active built-in effects, composed per domain so that the vehicle always behaves
/// as if only the currently active stories had ever acted (Artery's stack restores in the wrong
/// order when stories end out of order):
/// - max speed: the most recently activated cap rules; the live max speed is recorded when the
///   first cap arrives and restored when the last one leaves;
/// - speed hold: the most recently activated Stop or EmergencyStop rules; the speed mode is
///   recorded for an EmergencyStop and restored when handing over to Stop or releasing;
/// - speed factor, type and colour: the most recently activated one rules (LatestWins), the value
///   from before the first comes back after the last. A type brings its own max speed and maps
///   the speed factor onto its own distribution, so a type change under an active cap or factor
///   records the new type's own values and renews the cap and the factor;
/// - lane: the most recently activated lane index rules, renewed each step (settle()) for the lane
///   count of the road the vehicle is on; after the last, the vehicle changes lanes freely again;
/// - route: the most recently activated route change rules; the destination (and via edges) from
///   before the first comes back after the last, by routing the vehicle from where it is then.
/// - speed transition: the most recently activated one commands the speed each step (setSpeed),
///   in the speed mode SpeedTransition::speedMode() says (exact, or keeping SUMO's safe gap; the
///   vehicle's max speed, hence any cap, holds either way); a Stop
///   or EmergencyStop rules over it while active; after the last, SUMO has the speed again;
/// - lateral transition: the most recently activated lane change or lane offset moves the vehicle
///   across its road each step (changeSublane, SUMO's sublane model), with SUMO's own lane changes
///   off and its lateral speed and acceleration bounds lifted; after the last they come back.
/// A command goes to SUMO only when a domain's effective value changes (and to keep a lane).
class SBSIM_API EffectStack {
public:
    using Token = std::uint64_t;  ///< identifies one effect activation
    enum class Hold { Stop, EmergencyStop };
    /// A route change: to `target` (default: the vehicle's own destination) through `via`.
    struct Route {
        std::optional<std::string> target;
        std::vector<std::string> via;
        bool operator==(const Route&) const = default;
    };
    /// Receives the warnings of commands SUMO refused (a route it found none for): the run goes on.
    using Warn = std::function<void(const std::string& message)>;
    /// How long one lane command keeps the vehicle on its lane; renewed every step before it ends.
    static constexpr double kLaneHoldSeconds = 5.0;

    /// Without `warn`, warnings go to stderr.
    explicit EffectStack(VehicleController& vehicle, Warn warn = {}) : vehicle_(&vehicle), warn_(std::move(warn)) {}

    /// A cap on the max speed; with `overSeconds` > 0 a vehicle faster than the cap slows down to
    /// it linearly over that time (SUMO's slowDown) and the cap is set after it, so SUMO brakes no
    /// harder than the ramp asks. It composes like any cap: the latest rules.
    void pushSpeedCap(Token token, double mps, double overSeconds = 0);
    void pushHold(Token token, Hold hold);
    void pushSpeedFactor(Token token, double factor);
    void pushType(Token token, std::string typeId);
    void pushColor(Token token, Color color);
    /// Keeps the vehicle on lane `index` (from the right, 0-based; clamped to the road's lanes).
    void pushLane(Token token, int index);
    void pushRoute(Token token, Route route);
    /// A speed change commanded step by step from the next settle() on.
    void pushSpeedTransition(Token token, SpeedTransition transition);
    /// A lateral manoeuvre commanded step by step from the next settle() on; throws
    /// std::runtime_error when SUMO runs without its sublane model.
    void pushLateralTransition(Token token, LateralTransition transition);
    /// Removes the activation `token` from whichever domain holds it; unknown tokens are ignored.
    void remove(Token token);
    /// Called each step with the vehicle's speed while settling(): an EmergencyStop braking with
    /// slowDown() is turned into a hold once the vehicle stands, since SUMO lets it drive on after
    /// slowDown; a lane is renewed.
    /// `now`: the step's time (a gradual cap is set once its ramp has run).
    void settle(double speed, kernel::SimTime now = kernel::SimTime::zero()) {
        if (!holds_.empty()) settleHold(speed);
        if (!lanes_.empty()) holdLane();
        if (ramp_) settleRamp(now);
        if (!speedTransitions_.empty() && holds_.empty()) settleSpeedTransition(speed, now);
        if (!laterals_.empty()) settleLateral(speed, now);
    }

    bool empty() const {
        return caps_.empty() && holds_.empty() && factors_.empty() && types_.empty() && colors_.empty() &&
               lanes_.empty() && routes_.empty() && speedTransitions_.empty() && laterals_.empty();
    }
    /// Whether settle() has work: a Stop, EmergencyStop or lane is active, or a gradual cap ramps.
    bool settling() const {
        return !holds_.empty() || !lanes_.empty() || ramp_.has_value() || !speedTransitions_.empty() ||
               !laterals_.empty();
    }
    std::optional<double> effectiveCap() const;
    std::optional<Hold> effectiveHold() const;
    std::optional<double> effectiveSpeedFactor() const { return factors_.effective(); }
    std::optional<std::string> effectiveType() const { return types_.effective(); }
    std::optional<Color> effectiveColor() const { return colors_.effective(); }
    std::optional<int> effectiveLane() const { return lanes_.effective(); }
    std::optional<Route> effectiveRoute() const { return routes_.effective(); }
    /// The ruling speed transition / lateral transition, if any.
    const SpeedTransition* effectiveSpeedTransition() const {
        return speedTransitions_.empty() ? nullptr : &speedTransitions_.back().second;
    }
    const LateralTransition* effectiveLateral() const { return laterals_.empty() ? nullptr : &laterals_.back().second; }

private:
    void settleHold(double speed);
    void settleRamp(kernel::SimTime now);
    void applyCap(std::optional<double> before);
    void applyHold(std::optional<Hold> before);
    void applyType(const std::string& typeId);
    std::string ownType() const;
    void holdLane();
    void releaseLane();
    Route ownRoute() const;
    void applyRoute(const Route& route, const std::vector<std::string>& viaBefore);
    void warn(const std::string& message) const;
    void settleSpeedTransition(double speed, kernel::SimTime now);
    void settleLateral(double speed, kernel::SimTime now);
    void endSpeedTransitions();
    void endLaterals();

    VehicleController* vehicle_;
    Warn warn_;
    std::vector<std::pair<Token, double>> caps_;      // activation order
    std::vector<std::pair<Token, double>> capRamps_;  // s, of the gradual caps in caps_
    /// A gradual cap slowing the vehicle down: set as max speed when its ramp has run (the first
    /// settle() after the push gives the start).
    struct Ramp {
        double cap = 0;
        double seconds = 0;
        std::optional<kernel::SimTime> start;
    };
    std::optional<Ramp> ramp_;
    std::vector<std::pair<Token, Hold>> holds_;  // activation order
    double recordedMaxSpeed_ = 0;
    std::optional<int> recordedSpeedMode_;
    bool emergencyHeld_ = false;  // the EmergencyStop's vehicle stands and is held at 0
    LatestWins<double> factors_;
    LatestWins<std::string> types_;
    LatestWins<Color> colors_;
    LatestWins<int> lanes_;
    std::string laneRoad_;  // the road whose lane count laneRoadLanes_ is
    int laneRoadLanes_ = 0;
    LatestWins<Route> routes_;
    std::vector<std::pair<Token, SpeedTransition>> speedTransitions_;  // activation order
    int transitionSpeedMode_ = 0;            // the speed mode from before the first speed transition
    std::optional<int> commandedSpeedMode_;  // the one a speed transition set last, if still in force
    std::vector<std::pair<Token, LateralTransition>> laterals_;  // activation order
    struct LateralSettings {
        int laneChangeMode = 0;
        double maxSpeedLat = 0;
        std::string accelLat;
    };
    LateralSettings lateralSettings_;  // from before the first lateral transition
};

}  // namespace sbsim::traffic
