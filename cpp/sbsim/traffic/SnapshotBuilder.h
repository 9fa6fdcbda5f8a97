#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/ParallelFor.h"
#include "sbsim/traffic/SnapshotColumns.h"
#include "sbsim/traffic/VehicleController.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic {

/// Keeps the set of running vehicles and refills a VehicleSnapshot from libsumo after each step.
///
/// libsumo's per-vehicle getters were measured against variable subscriptions
/// (Vehicle::subscribe + getAllSubscriptionResults, which allocates a result object per value):
/// getters won clearly (bench/README.md), so getters it is. Each getter looks the vehicle up by id,
/// and that lookup dominates, so the builder asks as little as it can: length, width and type are
/// read once, at departure; max speed at departure and again only after a VehicleController told
/// it of a change (maxSpeedChanged()); acceleration is derived from the speed change over the step, exactly as
/// SUMO computes it (the getter only for a vehicle's first step). The reads are independent per
/// vehicle and read-only, so they are spread over the machine's cores. A vehicle's lane is interned
/// only when it changes.
class SnapshotBuilder : public MaxSpeedListener {
public:
    /// The values to read from now on (default: all). Constant values it adds are read at once for
    /// the vehicles already running.
    void setColumns(SnapshotColumns columns);
    SnapshotColumns columns() const { return columns_; }
    /// Vehicles that entered the network; reads their constant values.
    void addVehicles(const std::vector<std::string>& ids);
    /// Vehicles that left the network.
    void removeVehicles(const std::vector<std::string>& ids);
    /// Reads every running vehicle's per-step values into `out`, the reads spread over `parallel`.
    void fill(VehicleSnapshot& out, kernel::SimTime time, kernel::ParallelFor& parallel);
    void setStepLength(double seconds) { stepSeconds_ = seconds; }

    std::size_t running() const { return running_.size(); }
    bool isRunning(const std::string& id) const { return running_.contains(id); }

    /// `id`'s max speed was changed by a command: it is read again at the next fill. Called by the
    /// VehicleControllers given this builder (through SumoBridge::maxSpeedListener()).
    void maxSpeedChanged(const std::string& id) override;

private:
    struct Record {
        double length = 0;
        double width = 0;
        std::int32_t type = 0;
        std::string lane;             // last lane id read
        std::int32_t laneIndex = -1;  // interned index of `lane`; -1: changed, intern it
        std::int32_t road = -1;
        double speed = 0;  // at the previous step
        bool hasSpeed = false;
        double maxSpeed = 0;
    };
    std::int32_t intern(const std::string& s);
    void readConstants(const std::string& id, Record& r, SnapshotColumns columns);
    std::int32_t roadOfLane(std::int32_t lane);
    void resize(VehicleSnapshot& out, std::size_t n) const;

    SnapshotColumns columns_ = SnapshotColumns::all();
    double stepSeconds_ = 1;
    std::map<std::string, Record> running_;                      // ascending byte order
    std::vector<std::pair<const std::string*, Record*>> order_;  // running_ as an indexable list
    bool orderStale_ = true;
    std::uint64_t idsVersion_ = 0;  // VehicleSnapshot::idsVersion() of order_'s ids (0: none yet)
    std::unordered_map<std::string, std::int32_t> internIndex_;
    std::vector<std::string> strings_;
    std::vector<std::int32_t> laneRoad_;        // by interned lane index; -1 unknown
    std::mutex maxSpeedMutex_;                  // a story's Python threads may command vehicles too
    std::vector<std::string> maxSpeedChanges_;  // since the last fill
};

}  // namespace sbsim::traffic
