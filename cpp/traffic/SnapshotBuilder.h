#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "kernel/ParallelFor.h"
#include "traffic/VehicleSnapshot.h"

namespace sbsim::traffic {

/// Keeps the set of running vehicles and refills a VehicleSnapshot from libsumo after each step.
///
/// libsumo's per-vehicle getters were measured against variable subscriptions
/// (Vehicle::subscribe + getAllSubscriptionResults, which allocates a result object per value):
/// getters won clearly (bench/README.md), so getters it is. Each getter looks the vehicle up by id,
/// and that lookup dominates; the reads are independent per vehicle and read-only, so they are
/// spread over the machine's cores. Values that never change for a vehicle (length, width, type)
/// are read once, at departure; a vehicle's lane is interned only when it changes.
class SnapshotBuilder {
public:
    /// `threads`: total threads for reading (0 = all cores).
    explicit SnapshotBuilder(unsigned threads = 0) : parallel_(threads) {}

    /// Vehicles that entered the network; reads their constant values.
    void addVehicles(const std::vector<std::string>& ids);
    /// Vehicles that left the network.
    void removeVehicles(const std::vector<std::string>& ids);
    /// Reads every running vehicle's per-step values into `out`.
    void fill(VehicleSnapshot& out, kernel::SimTime time);

    std::size_t running() const { return running_.size(); }

private:
    struct Record {
        double length = 0;
        double width = 0;
        std::int32_t type = 0;
        std::string lane;          // last lane id read
        std::int32_t laneIndex = -1;  // interned index of `lane`; -1: changed, intern it
        std::int32_t road = -1;
    };
    std::int32_t intern(const std::string& s);
    std::int32_t roadOfLane(std::int32_t lane);
    void resize(VehicleSnapshot& out, std::size_t n) const;

    kernel::ParallelFor parallel_;
    std::map<std::string, Record> running_;  // ascending byte order
    std::vector<std::pair<const std::string*, Record*>> order_;  // running_ as an indexable list
    bool orderStale_ = true;
    std::unordered_map<std::string, std::int32_t> internIndex_;
    std::vector<std::string> strings_;
    std::vector<std::int32_t> laneRoad_;  // by interned lane index; -1 unknown
};

}  // namespace sbsim::traffic
