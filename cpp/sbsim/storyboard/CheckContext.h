#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/ConditionArea.h"
#include "sbsim/storyboard/TimeWindow.h"

namespace sbsim::storyboard {

/// What `sbsim check` knows of the scenario a story set will run in (the app fills it after SUMO
/// loaded). A question left unset cannot be answered: nothing is warned about it.
struct SBSIM_API CheckScenario {
    Eigen::Matrix2d boundary = Eigen::Matrix2d::Zero();  ///< SUMO's net boundary: (xmin, ymin), (xmax, ymax)
    kernel::SimTime begin;
    std::optional<kernel::SimTime> end;
    /// Whether a route file defines this vehicle id (flows: "<flow id>.<n>").
    std::function<bool(std::string_view)> vehicleDefined;
    /// Whether the loaded network has this edge (internal ones too), lane, traffic light.
    std::function<bool(std::string_view)> edgeExists;
    std::function<bool(std::string_view)> laneExists;
    std::function<bool(std::string_view)> trafficLightExists;
    /// Whether SUMO knows this vehicle type (or a route file defines it).
    std::function<bool(std::string_view)> vehicleTypeExists;
};

/// One thing that looks wrong in a story; the run would not fail, but likely not do what was meant.
struct SBSIM_API CheckWarning {
    std::string story;
    std::string message;
    /// It names a network object or vehicle type that does not exist: a run refuses the story.
    bool unknownId = false;
};

/// The kinds of network ids a story may name.
enum class NetworkObject { Edge, Lane, TrafficLight, VehicleType };

/// What a condition or effect's check hook asks about the scenario, and where it reports its
/// warnings (attributed to the story being checked).
class SBSIM_API CheckContext {
public:
    /// `spawned`: the vehicle ids the stories' world effects add, as defined as the route files' ones.
    CheckContext(const CheckScenario& scenario, std::set<std::string> spawned);

    const CheckScenario& scenario() const { return scenario_; }
    kernel::SimTime runBegin() const { return scenario_.begin; }
    /// The run's end, or the end of time when none is set.
    kernel::SimTime runEnd() const { return scenario_.end.value_or(kernel::SimTime::max()); }
    /// Whether a route file or a story defines the vehicle (true when the scenario cannot tell).
    bool vehicleDefined(std::string_view id) const;
    /// Whether the network has the object (true when the scenario cannot tell).
    bool exists(NetworkObject kind, std::string_view id) const;

    /// Warns "<who> names <kind>s … does not have: a, b" for those of `ids` that do not exist.
    void warnUnknown(std::string_view who, NetworkObject kind, const std::vector<std::string>& ids);
    /// Warns when `area` lies wholly outside the network boundary, naming `who` and, when read in the
    /// other frame it would fit, that frame.
    void warnOutsideNetwork(std::string_view who, const ConditionArea& area);

    /// Warns that `who` can never hold when `window` is empty (a conjunction of time windows that
    /// do not overlap).
    void warnNeverHolds(std::string_view who, const std::optional<TimeWindow>& window);

    /// The story the following warnings belong to.
    void beginStory(std::string name) { story_ = std::move(name); }
    void warn(std::string message) { warnings_.push_back({story_, std::move(message)}); }
    std::vector<CheckWarning>& warnings() { return warnings_; }

private:
    const CheckScenario& scenario_;
    std::set<std::string> spawned_;
    std::string story_;
    std::vector<CheckWarning> warnings_;
};

}  // namespace sbsim::storyboard
