#include "traffic/SnapshotBuilder.h"

#include <libsumo/Lane.h>
#include <libsumo/TraCIConstants.h>
#include <libsumo/Vehicle.h>

namespace sbsim::traffic {

namespace {
const std::vector<int> kSubscribedVariables = {libsumo::VAR_POSITION,     libsumo::VAR_SPEED,
                                               libsumo::VAR_ANGLE,        libsumo::VAR_ACCELERATION,
                                               libsumo::VAR_LANE_ID,      libsumo::VAR_MAXSPEED};
}  // namespace

std::int32_t SnapshotBuilder::intern(const std::string& s) {
    const auto [it, inserted] = internIndex_.try_emplace(s, static_cast<std::int32_t>(strings_.size()));
    if (inserted) strings_.push_back(s);
    return it->second;
}

std::int32_t SnapshotBuilder::roadOfLane(std::int32_t lane) {
    const auto it = laneRoad_.find(lane);
    if (it != laneRoad_.end()) return it->second;
    // A teleporting vehicle has no lane: its road is empty as well.
    const std::string& laneId = strings_[lane];
    const std::int32_t road = intern(laneId.empty() ? std::string() : libsumo::Lane::getEdgeID(laneId));
    laneRoad_.emplace(lane, road);
    return road;
}

void SnapshotBuilder::addVehicles(const std::vector<std::string>& ids) {
    for (const std::string& id : ids) {
        Constants c{libsumo::Vehicle::getLength(id), libsumo::Vehicle::getWidth(id),
                    intern(libsumo::Vehicle::getTypeID(id))};
        if (running_.insert_or_assign(id, c).second && method_ == Method::Subscriptions) {
            libsumo::Vehicle::subscribe(id, kSubscribedVariables);
        }
    }
}

void SnapshotBuilder::removeVehicles(const std::vector<std::string>& ids) {
    for (const std::string& id : ids) running_.erase(id);
}

void SnapshotBuilder::resize(VehicleSnapshot& out, std::size_t n) const {
    const auto m = static_cast<Eigen::Index>(n);
    out.ids_.resize(n);
    out.position_.resize(2, m);
    out.speed_.resize(m);
    out.angle_.resize(m);
    out.acceleration_.resize(m);
    out.length_.resize(m);
    out.width_.resize(m);
    out.maxSpeed_.resize(m);
    out.road_.resize(n);
    out.lane_.resize(n);
    out.type_.resize(n);
}

void SnapshotBuilder::fill(VehicleSnapshot& out, kernel::SimTime time) {
    out.time_ = time;
    resize(out, running_.size());
    const libsumo::SubscriptionResults results =
        method_ == Method::Subscriptions ? libsumo::Vehicle::getAllSubscriptionResults() : libsumo::SubscriptionResults();
    Eigen::Index i = 0;
    for (const auto& [id, c] : running_) {
        if (out.ids_[i] != id) out.ids_[i] = id;  // most ids keep their slot between steps: no reallocation
        out.length_[i] = c.length;
        out.width_[i] = c.width;
        out.type_[i] = c.type;
        std::int32_t lane = 0;
        if (method_ == Method::Getters) {
            const libsumo::TraCIPosition p = libsumo::Vehicle::getPosition(id);
            out.position_(0, i) = p.x;
            out.position_(1, i) = p.y;
            out.speed_[i] = libsumo::Vehicle::getSpeed(id);
            out.angle_[i] = libsumo::Vehicle::getAngle(id);
            out.acceleration_[i] = libsumo::Vehicle::getAcceleration(id);
            out.maxSpeed_[i] = libsumo::Vehicle::getMaxSpeed(id);
            lane = intern(libsumo::Vehicle::getLaneID(id));
        } else {
            const libsumo::TraCIResults& r = results.at(id);
            const auto& p = static_cast<const libsumo::TraCIPosition&>(*r.at(libsumo::VAR_POSITION));
            out.position_(0, i) = p.x;
            out.position_(1, i) = p.y;
            const auto value = [&](int var) { return static_cast<const libsumo::TraCIDouble&>(*r.at(var)).value; };
            out.speed_[i] = value(libsumo::VAR_SPEED);
            out.angle_[i] = value(libsumo::VAR_ANGLE);
            out.acceleration_[i] = value(libsumo::VAR_ACCELERATION);
            out.maxSpeed_[i] = value(libsumo::VAR_MAXSPEED);
            lane = intern(static_cast<const libsumo::TraCIString&>(*r.at(libsumo::VAR_LANE_ID)).value);
        }
        out.lane_[i] = lane;
        out.road_[i] = roadOfLane(lane);
        ++i;
    }
    // Interned strings only ever grow: append the new ones.
    out.strings_.insert(out.strings_.end(), strings_.begin() + static_cast<std::ptrdiff_t>(out.strings_.size()), strings_.end());
}

}  // namespace sbsim::traffic
