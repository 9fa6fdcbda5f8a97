#include "sbsim/storyboard/CheckContext.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "sbsim/storyboard/DescribeText.h"
#include "sbsim/storyboard/StoryAreas.h"

namespace sbsim::storyboard {

namespace {

/// Where points the script gave in one frame land when read in the other: the canvas frame has
/// its origin at the boundary's top-left with y downwards, SUMO's at its own origin with y up.
std::vector<Eigen::Vector2d> otherFrame(const std::vector<Eigen::Vector2d>& points, const Eigen::Matrix2d& b,
                                        bool givenAsCanvas) {
    std::vector<Eigen::Vector2d> out;
    for (const Eigen::Vector2d& p : points) {
        // Undo the conversion the script's frame made, and apply the other one.
        const Eigen::Vector2d written = givenAsCanvas ? Eigen::Vector2d(p.x() - b(0, 0), b(1, 1) - p.y()) : p;
        out.emplace_back(givenAsCanvas ? written : Eigen::Vector2d(written.x() + b(0, 0), b(1, 1) - written.y()));
    }
    return out;
}

bool overlapsBoundary(const std::vector<Eigen::Vector2d>& points, const Eigen::Matrix2d& b) {
    double xmin = points.front().x(), xmax = xmin, ymin = points.front().y(), ymax = ymin;
    for (const auto& p : points) {
        xmin = std::min(xmin, p.x());
        xmax = std::max(xmax, p.x());
        ymin = std::min(ymin, p.y());
        ymax = std::max(ymax, p.y());
    }
    // b's columns are (xmin, ymin) and (xmax, ymax).
    return xmax >= b(0, 0) && xmin <= b(0, 1) && ymax >= b(1, 0) && ymin <= b(1, 1);
}

/// The scenario's question about one kind of id, and how a warning says an id failed it.
struct IdQuestion {
    std::function<bool(std::string_view)> CheckScenario::*exists;
    const char* missing;
};

IdQuestion questionFor(NetworkObject kind) {
    switch (kind) {
        case NetworkObject::Edge:
            return {&CheckScenario::edgeExists, "edges the network does not have"};
        case NetworkObject::Lane:
            return {&CheckScenario::laneExists, "lanes the network does not have"};
        case NetworkObject::TrafficLight:
            return {&CheckScenario::trafficLightExists, "traffic lights the network does not have"};
        case NetworkObject::VehicleType:
            return {&CheckScenario::vehicleTypeExists, "vehicle types SUMO did not load"};
    }
    throw std::logic_error("unknown NetworkObject");
}

}  // namespace

CheckContext::CheckContext(const CheckScenario& scenario, std::set<std::string> spawned)
    : scenario_(scenario), spawned_(std::move(spawned)) {}

bool CheckContext::vehicleDefined(std::string_view id) const {
    return !scenario_.vehicleDefined || scenario_.vehicleDefined(id) || spawned_.contains(std::string(id));
}

bool CheckContext::exists(NetworkObject kind, std::string_view id) const {
    const std::function<bool(std::string_view)>& exists = scenario_.*questionFor(kind).exists;
    return !exists || exists(id);
}

void CheckContext::warnUnknown(std::string_view who, NetworkObject kind, const std::vector<std::string>& ids) {
    std::set<std::string> unknown;
    for (const std::string& id : ids) {
        if (!exists(kind, id)) unknown.insert(id);
    }
    if (unknown.empty()) return;
    warnings_.push_back(
        {story_, fmt::format("{} names {}: {}", who, questionFor(kind).missing, describeIds(unknown)), true});
}

void CheckContext::warnNeverHolds(std::string_view who, const std::optional<TimeWindow>& window) {
    if (window && window->empty()) warn(fmt::format("{} can never hold: its time windows do not overlap", who));
}

void CheckContext::warnOutsideNetwork(std::string_view who, const ConditionArea& area) {
    const Eigen::Matrix2d& b = scenario_.boundary;
    const std::vector<Eigen::Vector2d> points = outline(area);
    if (points.empty() || overlapsBoundary(points, b)) return;
    const bool canvas = area.given == GivenFrame::Canvas;
    std::string hint = "; read in the other frame it misses the network too";
    if (overlapsBoundary(otherFrame(points, b, canvas), b)) {
        hint = canvas ? "; it fits in the SUMO frame: give its points as (x, y) tuples, not Coord"
                      : "; it fits in Artery's canvas frame: give its points as Coord(x, y), not tuples";
    }
    warn(fmt::format("{} lies outside the network boundary ({:g}, {:g})-({:g}, {:g}){}", who, b(0, 0), b(1, 0), b(0, 1),
                     b(1, 1), hint));
}

}  // namespace sbsim::storyboard
