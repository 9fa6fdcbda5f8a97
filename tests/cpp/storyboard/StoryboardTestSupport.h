#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/EvaluationContext.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard::test {

using kernel::SimTime;
using Vehicle = traffic::VehicleSnapshot::Vehicle;

/// A vehicle at front bumper (x, y), driving at `speed` m/s with SUMO angle `angle` (degrees).
inline Vehicle car(std::string id, double x, double y, double speed = 0, double angle = 0, double length = 5,
                   double width = 1.8) {
    Vehicle v;
    v.id = std::move(id);
    v.x = x;
    v.y = y;
    v.speed = speed;
    v.angle = angle;
    v.length = length;
    v.width = width;
    return v;
}

/// A vehicle that matters only for its speed (m/s), at the origin.
inline Vehicle car(std::string id, double speed) { return car(std::move(id), 0, 0, speed); }

/// One step as the board sees it: a snapshot built by hand and its neighbour grid.
class Scene {
public:
    /// `stations`: what the vehicles heard over V2X, for the V2X conditions (none by default).
    explicit Scene(std::vector<Vehicle> vehicles, SimTime time = SimTime::zero(), double cellSize = 100,
                   const facilities::StationRegistry* stations = nullptr)
        : stations_(stations) {
        set(std::move(vehicles), time, cellSize);
    }
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    /// Replaces the step (a later time for the stateful conditions).
    void set(std::vector<Vehicle> vehicles, SimTime time, double cellSize = 100) {
        snapshot_.assign(std::move(vehicles), time);
        grid_.build(snapshot_, cellSize);
    }

    const EvaluationContext& ctx() const { return ctx_; }
    const traffic::NeighbourGrid& grid() const { return grid_; }
    const traffic::VehicleSnapshot& snapshot() const { return snapshot_; }
    VehicleIndex index(std::string_view id) const {
        const auto i = snapshot_.indexOf(id);
        if (!i) throw std::invalid_argument("no vehicle " + std::string(id));
        return *i;
    }

    /// Evaluates `c` for vehicle `id`, after prepare() as the board does each step.
    ConditionResult test(Condition& c, std::string_view id) const {
        c.prepare(ctx_);
        return c.test(ctx_, index(id));
    }
    /// The ids of a result's other vehicles, in result order.
    std::vector<std::string> others(const ConditionResult& r) const {
        std::vector<std::string> ids;
        for (const VehicleIndex i : r.others()) ids.push_back(snapshot_.ids()[i]);
        return ids;
    }

private:
    traffic::VehicleSnapshot snapshot_;
    traffic::NeighbourGrid grid_;
    const facilities::StationRegistry* stations_;
    EvaluationContext ctx_{snapshot_, grid_, nullptr, nullptr, stations_};
};

/// A condition that returns a fixed result and counts its evaluations (to see laziness).
class ProbeCondition : public Condition {
public:
    explicit ProbeCondition(ConditionResult result) : result_(std::move(result)) {}
    ConditionResult test(const EvaluationContext& /*ctx*/, VehicleIndex /*ego*/) override {
        ++calls;
        return result_;
    }
    int calls = 0;

private:
    ConditionResult result_;
};

using Ids = std::vector<std::string>;

}  // namespace sbsim::storyboard::test
