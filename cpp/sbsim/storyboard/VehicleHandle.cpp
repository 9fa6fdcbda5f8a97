#include "sbsim/storyboard/VehicleHandle.h"

#include <fmt/format.h>

#include <cmath>

namespace sbsim::storyboard {

namespace {

void requireFinite(double value, const char* what, const char* method) {
    if (!std::isfinite(value))
        throw std::invalid_argument(fmt::format("{}: {} must be finite, got {}", method, what, value));
}

void requireNonNegative(double value, const char* what, const char* method) {
    requireFinite(value, what, method);
    if (value < 0) throw std::invalid_argument(fmt::format("{}: {} must be >= 0, got {}", method, what, value));
}

}  // namespace

traffic::VehicleController& VehicleHandle::get() const {
    // The storyboard owns the controller for the vehicle's life; locking for the call's length
    // is enough, as nothing in one call can make the vehicle leave.
    const std::shared_ptr<traffic::VehicleController> controller = controller_.lock();
    if (!controller) {
        throw VehicleGone(
            fmt::format("vehicle '{}' has left the simulation; its VehicleController can no longer be used", id_));
    }
    return *controller;
}

void VehicleHandle::setMaxSpeed(double mps) {
    requireNonNegative(mps, "the speed", "set_max_speed");
    get().setMaxSpeed(mps);
}

void VehicleHandle::setSpeed(double mps) {
    requireFinite(mps, "the speed", "set_speed");
    get().setSpeed(mps);
}

void VehicleHandle::slowDown(double mps, double seconds) {
    requireNonNegative(mps, "the speed", "slow_down");
    requireNonNegative(seconds, "the duration", "slow_down");
    get().slowDown(mps, seconds);
}

void VehicleHandle::setSpeedMode(int mode) { get().setSpeedMode(mode); }

void VehicleHandle::changeLane(int laneIndex, double seconds) {
    if (laneIndex < 0)
        throw std::invalid_argument(fmt::format("change_lane: the lane index must be >= 0, got {}", laneIndex));
    requireNonNegative(seconds, "the duration", "change_lane");
    get().changeLane(laneIndex, seconds);
}

}  // namespace sbsim::storyboard
