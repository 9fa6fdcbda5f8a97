#include "sbsim/traffic/VehicleSnapshot.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <unordered_map>

namespace sbsim::traffic {

std::uint64_t VehicleSnapshot::nextGeneration() {
    static std::atomic<std::uint64_t> next{1};
    return next.fetch_add(1, std::memory_order_relaxed);
}

std::optional<VehicleSnapshot::Index> VehicleSnapshot::indexOf(std::string_view id) const {
    const auto it = std::lower_bound(ids_.begin(), ids_.end(), id,
                                     [](const std::string& a, std::string_view b) { return std::string_view(a) < b; });
    if (it == ids_.end() || *it != id) return std::nullopt;
    return static_cast<Index>(it - ids_.begin());
}

}  // namespace sbsim::traffic

namespace sbsim::traffic {

namespace {

/// The seven numeric columns, writable and sized for `n` vehicles. Every element is written after,
/// so a column a reader holds is left to it unchanged (a fresh array takes its place).
struct Resized {
    Eigen::Matrix2Xd& position;
    Eigen::VectorXd &speed, &angle, &acceleration, &length, &width, &maxSpeed;
};

Resized resized(Eigen::Index n, SharedColumn<Eigen::Matrix2Xd>& position, SharedColumn<Eigen::VectorXd>& speed,
                SharedColumn<Eigen::VectorXd>& angle, SharedColumn<Eigen::VectorXd>& acceleration,
                SharedColumn<Eigen::VectorXd>& length, SharedColumn<Eigen::VectorXd>& width,
                SharedColumn<Eigen::VectorXd>& maxSpeed) {
    Resized out{*position.writable(false),     *speed.writable(false),  *angle.writable(false),
                *acceleration.writable(false), *length.writable(false), *width.writable(false),
                *maxSpeed.writable(false)};
    out.position.resize(2, n);
    for (Eigen::VectorXd* column : {&out.speed, &out.angle, &out.acceleration, &out.length, &out.width, &out.maxSpeed})
        column->resize(n);
    return out;
}

}  // namespace

void VehicleSnapshot::assign(std::vector<Vehicle> vehicles, kernel::SimTime time) {
    std::sort(vehicles.begin(), vehicles.end(), [](const Vehicle& a, const Vehicle& b) { return a.id < b.id; });
    for (std::size_t i = 1; i < vehicles.size(); ++i) {
        if (vehicles[i].id == vehicles[i - 1].id)
            throw std::invalid_argument("duplicate vehicle id '" + vehicles[i].id + "'");
    }
    const auto n = static_cast<Eigen::Index>(vehicles.size());
    // The same vehicles as before keep the id list's version.
    const bool sameIds = std::equal(vehicles.begin(), vehicles.end(), ids_.begin(), ids_.end(),
                                    [](const Vehicle& v, const std::string& id) { return v.id == id; });
    if (!sameIds) idsVersion_ = nextGeneration();
    time_ = time;
    columns_ = SnapshotColumns::all();
    ids_.clear();
    strings_.clear();
    generation_ = nextGeneration();
    road_.clear();
    lane_.clear();
    type_.clear();
    const Resized c = resized(n, position_, speed_, angle_, acceleration_, length_, width_, maxSpeed_);
    Eigen::Matrix2Xd& position = c.position;
    Eigen::VectorXd &speed = c.speed, &angle = c.angle, &acceleration = c.acceleration;
    Eigen::VectorXd &length = c.length, &width = c.width, &maxSpeed = c.maxSpeed;
    std::unordered_map<std::string, std::int32_t> interned;
    const auto intern = [&](const std::string& s) {
        const auto [it, inserted] = interned.try_emplace(s, static_cast<std::int32_t>(strings_.size()));
        if (inserted) strings_.push_back(s);
        return it->second;
    };
    for (Eigen::Index i = 0; i < n; ++i) {
        Vehicle& v = vehicles[i];
        position(0, i) = v.x;
        position(1, i) = v.y;
        speed[i] = v.speed;
        angle[i] = v.angle;
        acceleration[i] = v.acceleration;
        length[i] = v.length;
        width[i] = v.width;
        maxSpeed[i] = v.maxSpeed;
        road_.push_back(intern(v.road));
        lane_.push_back(intern(v.lane));
        type_.push_back(intern(v.type));
        ids_.push_back(std::move(v.id));
    }
}

void VehicleSnapshot::assignSubset(const VehicleSnapshot& from, const std::vector<Index>& keep) {
    if (&from == this) throw std::invalid_argument("assignSubset: a snapshot cannot be a subset of itself");
    const auto n = static_cast<Eigen::Index>(keep.size());
    time_ = from.time_;
    columns_ = from.columns_;
    // The source's table only grows within a generation: copy it only when it changed.
    if (generation_ != from.generation_ || strings_.size() != from.strings_.size()) {
        strings_ = from.strings_;
        generation_ = from.generation_;
    }
    bool sameIds = ids_.size() == keep.size();
    ids_.resize(keep.size());
    road_.resize(keep.size());
    lane_.resize(keep.size());
    type_.resize(keep.size());
    const Resized c = resized(n, position_, speed_, angle_, acceleration_, length_, width_, maxSpeed_);
    Eigen::Matrix2Xd& position = c.position;
    Eigen::VectorXd &speed = c.speed, &angle = c.angle, &acceleration = c.acceleration;
    Eigen::VectorXd &length = c.length, &width = c.width, &maxSpeed = c.maxSpeed;
    for (Eigen::Index k = 0; k < n; ++k) {
        const Index i = keep[static_cast<std::size_t>(k)];
        if (i < 0 || i >= from.size() || (k > 0 && i <= keep[static_cast<std::size_t>(k - 1)])) {
            idsVersion_ = nextGeneration();  // the ids may be half overwritten
            throw std::invalid_argument("assignSubset: indices must be ascending and within the snapshot");
        }
        if (ids_[k] != from.ids_[i]) {
            ids_[k] = from.ids_[i];
            sameIds = false;
        }
        road_[k] = from.road_[i];
        lane_[k] = from.lane_[i];
        type_[k] = from.type_[i];
        position.col(k) = from.position_->col(i);
        speed[k] = (*from.speed_)[i];
        angle[k] = (*from.angle_)[i];
        acceleration[k] = (*from.acceleration_)[i];
        length[k] = (*from.length_)[i];
        width[k] = (*from.width_)[i];
        maxSpeed[k] = (*from.maxSpeed_)[i];
    }
    if (!sameIds) idsVersion_ = nextGeneration();
}

}  // namespace sbsim::traffic
