#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "traffic/VehicleSnapshot.h"

namespace sbsim::traffic {

/// Keeps the set of running vehicles and refills a VehicleSnapshot from libsumo after each step.
/// Values that never change for a vehicle (length, width, type) are read once, at departure.
class SnapshotBuilder {
public:
    /// How the per-step values are read. Both are kept so bench/ can show which is faster.
    enum class Method { Getters, Subscriptions };

    explicit SnapshotBuilder(Method method = Method::Getters) : method_(method) {}

    /// Vehicles that entered the network (sorted or not); reads their constant values.
    void addVehicles(const std::vector<std::string>& ids);
    /// Vehicles that left the network.
    void removeVehicles(const std::vector<std::string>& ids);
    /// Reads every running vehicle's per-step values into `out`.
    void fill(VehicleSnapshot& out, kernel::SimTime time);

    std::size_t running() const { return running_.size(); }

private:
    struct Constants {
        double length;
        double width;
        std::int32_t type;
    };
    std::int32_t intern(const std::string& s);
    std::int32_t roadOfLane(std::int32_t lane);
    void resize(VehicleSnapshot& out, std::size_t n) const;

    Method method_;
    std::map<std::string, Constants> running_;  // ascending byte order
    std::unordered_map<std::string, std::int32_t> internIndex_;
    std::vector<std::string> strings_;
    std::unordered_map<std::int32_t, std::int32_t> laneRoad_;
};

}  // namespace sbsim::traffic
