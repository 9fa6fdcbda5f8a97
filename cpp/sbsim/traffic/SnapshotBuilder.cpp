#include "sbsim/traffic/SnapshotBuilder.h"

#include <libsumo/Lane.h>
#include <libsumo/Vehicle.h>

#include <mutex>

namespace sbsim::traffic {

void SnapshotBuilder::maxSpeedChanged(const std::string& id) {
    const std::lock_guard lock(maxSpeedMutex_);
    maxSpeedChanges_.push_back(id);
}

std::int32_t SnapshotBuilder::intern(const std::string& s) {
    const auto [it, inserted] = internIndex_.try_emplace(s, static_cast<std::int32_t>(strings_.size()));
    if (inserted) strings_.push_back(s);
    return it->second;
}

std::int32_t SnapshotBuilder::roadOfLane(std::int32_t lane) {
    if (lane >= static_cast<std::int32_t>(laneRoad_.size())) laneRoad_.resize(lane + 1, -1);
    if (laneRoad_[lane] < 0) {
        // A teleporting vehicle has no lane: its road is empty as well.
        const std::string laneId = strings_[lane];
        laneRoad_[lane] = intern(laneId.empty() ? std::string() : libsumo::Lane::getEdgeID(laneId));
    }
    return laneRoad_[lane];
}

void SnapshotBuilder::readConstants(const std::string& id, Record& r, SnapshotColumns columns) {
    if (columns.contains(SnapshotColumns::Size)) {
        r.length = libsumo::Vehicle::getLength(id);
        r.width = libsumo::Vehicle::getWidth(id);
    }
    if (columns.contains(SnapshotColumns::Type)) r.type = intern(libsumo::Vehicle::getTypeID(id));
    if (columns.contains(SnapshotColumns::MaxSpeed)) r.maxSpeed = libsumo::Vehicle::getMaxSpeed(id);
}

void SnapshotBuilder::setColumns(SnapshotColumns columns) {
    // Constant values a new reader wants are read now for the vehicles already running.
    SnapshotColumns added;
    for (const auto c : {SnapshotColumns::Size, SnapshotColumns::Type, SnapshotColumns::MaxSpeed}) {
        if (columns.contains(c) && !columns_.contains(c)) added |= c;
    }
    if (!added.empty()) {
        for (auto& [id, record] : running_) readConstants(id, record, added);
    }
    columns_ = columns;
}

void SnapshotBuilder::addVehicles(const std::vector<std::string>& ids) {
    for (const std::string& id : ids) {
        Record r;
        readConstants(id, r, columns_);
        running_.insert_or_assign(id, std::move(r));
    }
    orderStale_ = orderStale_ || !ids.empty();
}

void SnapshotBuilder::removeVehicles(const std::vector<std::string>& ids) {
    for (const std::string& id : ids) running_.erase(id);
    orderStale_ = orderStale_ || !ids.empty();
}

void SnapshotBuilder::resize(VehicleSnapshot& out, std::size_t n) const {
    out.ids_.resize(n);
    out.road_.resize(n);
    out.lane_.resize(n);
    out.type_.resize(n);
}

void SnapshotBuilder::fill(VehicleSnapshot& out, kernel::SimTime time, kernel::ParallelFor& parallel) {
    if (orderStale_) {
        order_.clear();
        order_.reserve(running_.size());
        for (auto& [id, record] : running_) order_.emplace_back(&id, &record);
        orderStale_ = false;
        idsVersion_ = VehicleSnapshot::nextGeneration();
    }
    // `out` holds these ids already unless a vehicle came or went (or it is another snapshot).
    const bool copyIds = out.idsVersion_ != idsVersion_;
    out.time_ = time;
    out.columns_ = columns_;
    resize(out, order_.size());
    const bool position = columns_.contains(SnapshotColumns::Position);
    const bool speed = columns_.contains(SnapshotColumns::Speed) || columns_.contains(SnapshotColumns::Acceleration);
    const bool angle = columns_.contains(SnapshotColumns::Angle);
    const bool lane = columns_.contains(SnapshotColumns::Lane);
    // The arrays to write: the snapshot's own unless a Python view still holds them (then a spare,
    // SharedColumn). A column not read this step keeps its values.
    Eigen::Matrix2Xd& positions = *out.position_.writable(!position);
    Eigen::VectorXd& speeds = *out.speed_.writable(!speed);
    Eigen::VectorXd& accelerations = *out.acceleration_.writable(!speed);
    Eigen::VectorXd& angles = *out.angle_.writable(!angle);
    Eigen::VectorXd& lengths = *out.length_.writable(false);
    Eigen::VectorXd& widths = *out.width_.writable(false);
    Eigen::VectorXd& maxSpeeds = *out.maxSpeed_.writable(false);
    const auto m = static_cast<Eigen::Index>(order_.size());
    positions.resize(2, m);
    for (Eigen::VectorXd* column : {&speeds, &accelerations, &angles, &lengths, &widths, &maxSpeeds}) column->resize(m);
    {
        const std::lock_guard lock(maxSpeedMutex_);
        if (columns_.contains(SnapshotColumns::MaxSpeed)) {
            for (const std::string& id : maxSpeedChanges_) {
                if (const auto it = running_.find(id); it != running_.end())
                    it->second.maxSpeed = libsumo::Vehicle::getMaxSpeed(id);
            }
        }
        maxSpeedChanges_.clear();
    }

    // Independent per vehicle: each index is written by exactly one thread. Without per-step
    // columns there is nothing to ask SUMO, so no thread is woken.
    const auto read = [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            const std::string& id = *order_[k].first;
            Record& r = *order_[k].second;
            const auto i = static_cast<Eigen::Index>(k);
            if (copyIds && out.ids_[k] != id) out.ids_[k] = id;  // most ids keep their slot: no reallocation
            if (position) {
                const libsumo::TraCIPosition p = libsumo::Vehicle::getPosition(id);
                positions(0, i) = p.x;
                positions(1, i) = p.y;
            }
            if (speed) {
                const double v = libsumo::Vehicle::getSpeed(id);
                speeds[i] = v;
                accelerations[i] = r.hasSpeed ? (v - r.speed) / stepSeconds_ : libsumo::Vehicle::getAcceleration(id);
                r.speed = v;
                r.hasSpeed = true;
            }
            if (angle) angles[i] = libsumo::Vehicle::getAngle(id);
            maxSpeeds[i] = r.maxSpeed;
            lengths[i] = r.length;
            widths[i] = r.width;
            out.type_[k] = r.type;
            if (lane) {
                std::string laneId = libsumo::Vehicle::getLaneID(id);
                if (laneId != r.lane || r.laneIndex < 0) {
                    r.lane = std::move(laneId);
                    r.laneIndex = -1;
                }
            }
        }
    };
    if (columns_.perStep().empty()) {
        read(0, order_.size());
    } else {
        parallel.run(order_.size(), read);
    }
    // Interning touches shared tables: only for the few vehicles that changed lane, on one thread.
    for (std::size_t k = 0; lane && k < order_.size(); ++k) {
        Record& r = *order_[k].second;
        if (r.laneIndex < 0) {
            r.laneIndex = intern(r.lane);
            r.road = roadOfLane(r.laneIndex);
        }
        out.lane_[k] = r.laneIndex;
        out.road_[k] = r.road;
    }
    out.idsVersion_ = idsVersion_;
    // Interned strings only ever grow: append the new ones.
    out.strings_.insert(out.strings_.end(), strings_.begin() + static_cast<std::ptrdiff_t>(out.strings_.size()),
                        strings_.end());
}

}  // namespace sbsim::traffic
