#include "sbsim/traffic/EffectStack.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace sbsim::traffic {

std::optional<double> EffectStack::effectiveCap() const {
    if (caps_.empty()) return std::nullopt;
    return caps_.back().second;
}

std::optional<EffectStack::Hold> EffectStack::effectiveHold() const {
    if (holds_.empty()) return std::nullopt;
    return holds_.back().second;
}

void EffectStack::pushSpeedCap(Token token, double mps, double overSeconds) {
    const auto before = effectiveCap();
    if (!before) recordedMaxSpeed_ = vehicle_->maxSpeed();
    caps_.emplace_back(token, mps);
    if (overSeconds > 0) capRamps_.emplace_back(token, overSeconds);
    applyCap(before);
}

void EffectStack::pushHold(Token token, Hold hold) {
    const auto before = effectiveHold();
    holds_.emplace_back(token, hold);
    applyHold(before);
}

void EffectStack::pushSpeedFactor(Token token, double factor) {
    if (const auto v = factors_.push(token, factor, [this] { return vehicle_->speedFactor(); }))
        vehicle_->setSpeedFactor(*v);
}

void EffectStack::pushType(Token token, std::string typeId) {
    if (const auto v = types_.push(token, std::move(typeId), [this] { return ownType(); })) applyType(*v);
}

void EffectStack::pushColor(Token token, Color color) {
    if (const auto v = colors_.push(token, color, [this] { return vehicle_->color(); })) vehicle_->setColor(*v);
}

void EffectStack::pushLane(Token token, int index) {
    if (lanes_.push(token, index, [] { return 0; })) holdLane();
}

void EffectStack::pushRoute(Token token, Route route) {
    const std::optional<Route> before = routes_.effective();
    if (const auto v = routes_.push(token, std::move(route), [this] { return ownRoute(); }))
        applyRoute(*v, before ? before->via : routes_.original().via);
}

void EffectStack::pushSpeedTransition(Token token, SpeedTransition transition) {
    if (speedTransitions_.empty()) {
        // Under an EmergencyStop the live mode is its 0: the vehicle's own is the one it recorded.
        transitionSpeedMode_ = recordedSpeedMode_ ? *recordedSpeedMode_ : vehicle_->speedMode();
        commandedSpeedMode_.reset();
    }
    speedTransitions_.emplace_back(token, std::move(transition));
}

void EffectStack::settleSpeedTransition(double speed, kernel::SimTime now) {
    SpeedTransition& transition = speedTransitions_.back().second;
    const int mode = transition.speedMode(transitionSpeedMode_);
    if (mode != commandedSpeedMode_) {
        vehicle_->setSpeedMode(mode);
        commandedSpeedMode_ = mode;
    }
    const double driven = transition.needsOdometer() ? vehicle_->odometer() : 0.0;
    vehicle_->setSpeed(transition.next(now.seconds(), vehicle_->stepLength(), speed, driven));
}

void EffectStack::endSpeedTransitions() {
    commandedSpeedMode_.reset();
    if (holds_.empty()) vehicle_->setSpeed(-1);
    if (recordedSpeedMode_) {
        recordedSpeedMode_ = transitionSpeedMode_;  // an EmergencyStop gives it back when it ends
    } else {
        vehicle_->setSpeedMode(transitionSpeedMode_);
    }
}

// The keys of SUMO's sublane model this class lifts while a lateral transition runs.
namespace {
constexpr const char* kAccelLat = "laneChangeModel.lcAccelLat";
// Fast enough for any lateral move of one step: the transition's shape alone says how fast.
constexpr double kUnboundedLat = 1000.0;
}  // namespace

void EffectStack::pushLateralTransition(Token token, LateralTransition transition) {
    if (laterals_.empty()) {
        if (!vehicle_->sublaneModel()) {
            throw std::runtime_error(
                "a lateral transition needs SUMO's sublane model: run SUMO with --lateral-resolution (e.g. 0.8)");
        }
        lateralSettings_ = {vehicle_->laneChangeMode(), vehicle_->maxSpeedLat(), vehicle_->parameter(kAccelLat)};
        vehicle_->setLaneChangeMode(0);  // SUMO's own lane changes would fight the manoeuvre
        vehicle_->setMaxSpeedLat(kUnboundedLat);
        vehicle_->setParameter(kAccelLat, fmt::format("{:g}", kUnboundedLat));
    }
    laterals_.emplace_back(token, std::move(transition));
}

void EffectStack::settleLateral(double speed, kernel::SimTime now) {
    const std::string road = vehicle_->roadId();
    // On a junction (SUMO's internal roads, ':...') or off the road: the vehicle goes on as it is.
    if (road.empty() || road.front() == ':') return;
    LateralTransition& transition = laterals_.back().second;
    const double driven = transition.needsOdometer() ? vehicle_->odometer() : 0.0;
    const LateralPlace place{vehicle_->laneIndex(), vehicle_->lateralLanePosition()};
    const double move =
        transition.next(now.seconds(), vehicle_->stepLength(), place, vehicle_->laneWidths(), speed, driven);
    vehicle_->changeSublane(move);
}

void EffectStack::endLaterals() {
    vehicle_->setLaneChangeMode(lateralSettings_.laneChangeMode);
    vehicle_->setMaxSpeedLat(lateralSettings_.maxSpeedLat);
    if (!lateralSettings_.accelLat.empty()) vehicle_->setParameter(kAccelLat, lateralSettings_.accelLat);
}

std::string EffectStack::ownType() const {
    // A command that changed one vehicle's type parameters (setMaxSpeed) left it on SUMO's private
    // copy "<type>@<id>", which SUMO drops when the type is replaced: the type to come back is the
    // one that copy was made of.
    std::string type = vehicle_->typeId();
    const std::string suffix = "@" + vehicle_->id();
    if (type.size() > suffix.size() && type.ends_with(suffix)) type.resize(type.size() - suffix.size());
    return type;
}

void EffectStack::applyType(const std::string& typeId) {
    // SUMO carries the speed factor over to the new type (mapped onto its distribution), so it is
    // the vehicle's own factor that must cross over; the active one is set again after.
    const auto factor = factors_.effective();
    if (factor) vehicle_->setSpeedFactor(factors_.original());
    vehicle_->setType(typeId);
    if (factor) {
        factors_.setOriginal(vehicle_->speedFactor());
        vehicle_->setSpeedFactor(*factor);
    }
    if (const auto cap = effectiveCap()) {
        recordedMaxSpeed_ = vehicle_->maxSpeed();  // the new type's own, for when the caps end
        vehicle_->setMaxSpeed(*cap);
    }
}

void EffectStack::remove(Token token) {
    const auto matches = [token](const auto& entry) { return entry.first == token; };
    if (const auto it = std::find_if(caps_.begin(), caps_.end(), matches); it != caps_.end()) {
        const auto before = effectiveCap();
        caps_.erase(it);
        std::erase_if(capRamps_, matches);
        applyCap(before);
    } else if (const auto h = std::find_if(holds_.begin(), holds_.end(), matches); h != holds_.end()) {
        const auto before = effectiveHold();
        holds_.erase(h);
        applyHold(before);
    } else if (factors_.contains(token)) {
        if (const auto v = factors_.remove(token)) vehicle_->setSpeedFactor(*v);
    } else if (types_.contains(token)) {
        if (const auto v = types_.remove(token)) applyType(*v);
    } else if (colors_.contains(token)) {
        if (const auto v = colors_.remove(token)) vehicle_->setColor(*v);
    } else if (lanes_.contains(token)) {
        if (lanes_.remove(token)) lanes_.empty() ? releaseLane() : holdLane();
    } else if (const auto t = std::find_if(speedTransitions_.begin(), speedTransitions_.end(), matches);
               t != speedTransitions_.end()) {
        speedTransitions_.erase(t);  // an older one rules from the next settle() on
        if (speedTransitions_.empty()) endSpeedTransitions();
    } else if (const auto l = std::find_if(laterals_.begin(), laterals_.end(), matches); l != laterals_.end()) {
        laterals_.erase(l);
        if (laterals_.empty()) endLaterals();
    } else if (routes_.contains(token)) {
        const std::vector<std::string> viaBefore = routes_.effective()->via;
        if (const auto v = routes_.remove(token)) applyRoute(*v, viaBefore);
    }
}

void EffectStack::holdLane() {
    const std::string road = vehicle_->roadId();
    // On a junction (SUMO's internal roads, ':...') or off the road: the last command stands.
    if (road.empty() || road.front() == ':') return;
    if (road != laneRoad_) {
        laneRoad_ = road;
        laneRoadLanes_ = vehicle_->laneCount();
    }
    vehicle_->changeLane(std::min(*lanes_.effective(), laneRoadLanes_ - 1), kLaneHoldSeconds);
}

void EffectStack::releaseLane() {
    // A command for no time ends the held one: SUMO's lane-change model decides again.
    vehicle_->changeLane(vehicle_->laneIndex(), 0);
    laneRoad_.clear();
}

EffectStack::Route EffectStack::ownRoute() const {
    const std::vector<std::string> edges = vehicle_->route();
    return {edges.empty() ? std::nullopt : std::optional<std::string>(edges.back()), vehicle_->via()};
}

void EffectStack::applyRoute(const Route& route, const std::vector<std::string>& viaBefore) {
    // Routed from where the vehicle is now: the edges it drove are not given back.
    const std::optional<std::string>& target = route.target ? route.target : routes_.original().target;
    try {
        if (route.via != viaBefore) vehicle_->setVia(route.via);
        if (target) vehicle_->changeTarget(*target);
    } catch (const CommandRefused& e) {
        warn(fmt::format("vehicle '{}' keeps its route: {}", vehicle_->id(), e.what()));
    }
}

void EffectStack::warn(const std::string& message) const {
    if (warn_) {
        warn_(message);
    } else {
        std::fprintf(stderr, "sbsim: warning: %s\n", message.c_str());
    }
}

void EffectStack::applyCap(std::optional<double> before) {
    const auto now = effectiveCap();
    if (now == before) return;
    if (ramp_) {
        // Another cap (or none) rules now: SUMO's ramp ends here, unless a hold commands the speed.
        ramp_.reset();
        if (holds_.empty()) vehicle_->setSpeed(-1);
    }
    if (now && !capRamps_.empty() && capRamps_.back().first == caps_.back().first) {
        const double speed = vehicle_->speed();
        if (speed > *now) {
            // Down to the cap along SUMO's ramp; the cap itself follows once the ramp has run.
            vehicle_->slowDown(*now, capRamps_.back().second);
            ramp_ = Ramp{*now, capRamps_.back().second, std::nullopt};
            return;
        }
    }
    vehicle_->setMaxSpeed(now ? *now : recordedMaxSpeed_);
}

void EffectStack::settleRamp(kernel::SimTime now) {
    if (!ramp_->start) {
        ramp_->start = now;
        return;
    }
    if ((now - *ramp_->start).seconds() + 1e-9 < ramp_->seconds) return;
    vehicle_->setMaxSpeed(ramp_->cap);
    ramp_.reset();
}

void EffectStack::settleHold(double speed) {
    // A few cm/s: SUMO's standing vehicles report exactly 0, braking ones clearly more.
    constexpr double kStanding = 0.01;
    if (effectiveHold() == Hold::EmergencyStop && !emergencyHeld_ && speed <= kStanding) {
        vehicle_->setSpeed(0);
        emergencyHeld_ = true;
    }
}

void EffectStack::applyHold(std::optional<Hold> before) {
    const auto now = effectiveHold();
    if (now == before) return;
    emergencyHeld_ = false;
    if (commandedSpeedMode_) {
        // A hold brakes in the vehicle's own mode; a speed transition sets its own again after.
        vehicle_->setSpeedMode(transitionSpeedMode_);
        commandedSpeedMode_.reset();
    }
    if (!now) {
        vehicle_->setSpeed(-1);
        if (recordedSpeedMode_) vehicle_->setSpeedMode(*recordedSpeedMode_);
        recordedSpeedMode_.reset();
    } else if (*now == Hold::Stop) {
        // From EmergencyStop: give the vehicle its own speed checks back, then hold it.
        if (recordedSpeedMode_) vehicle_->setSpeedMode(*recordedSpeedMode_);
        recordedSpeedMode_.reset();
        vehicle_->setSpeed(0);
    } else {
        recordedSpeedMode_ = vehicle_->speedMode();
        vehicle_->setSpeedMode(0);
        const double v = vehicle_->speed();
        const double decel = vehicle_->emergencyDecel();
        if (v > 0 && decel > 0) {
            vehicle_->slowDown(0, v / decel);
        } else {
            vehicle_->setSpeed(0);
            emergencyHeld_ = true;
        }
    }
}

}  // namespace sbsim::traffic
