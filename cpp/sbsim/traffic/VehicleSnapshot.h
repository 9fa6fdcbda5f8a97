#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Object.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/traffic/SharedColumn.h"
#include "sbsim/traffic/SnapshotColumns.h"

namespace sbsim::traffic {

/// The state of every running vehicle after one SUMO step, as struct-of-arrays: column/element i
/// of every array belongs to vehicle ids()[i], and ids are in ascending byte order, so iteration is
/// deterministic. Conditions and services read this instead of calling libsumo per vehicle.
/// Strings that repeat across vehicles (road, lane, type) are stored once and indexed.
class SBSIM_API VehicleSnapshot : public kernel::Object {
public:
    using Index = std::int32_t;

    kernel::SimTime time() const { return time_; }
    /// The values this snapshot holds; the others are not read (their arrays hold stale values).
    /// A reader declares what it reads (Condition::columns(), SumoBridge::demandColumns).
    SnapshotColumns columns() const { return columns_; }
    Index size() const { return static_cast<Index>(ids_.size()); }
    bool empty() const { return ids_.empty(); }

    /// Ascending byte order (std::string comparison).
    const std::vector<std::string>& ids() const { return ids_; }
    /// Index of `id` in this step's arrays (binary search over the sorted ids), if running.
    std::optional<Index> indexOf(std::string_view id) const;
    /// Two snapshots (or one snapshot at two times) with the same idsVersion() have equal ids():
    /// a step in which no vehicle came or went keeps it, so work that carries per-vehicle rows
    /// from one step to the next (VehiclePass, TtcCondition's poses) may skip matching the ids.
    /// Unique process-wide; a different id list always gets a new one.
    std::uint64_t idsVersion() const { return idsVersion_; }

    const Eigen::Matrix2Xd& positions() const { return *position_; }         ///< SUMO network x, y (front bumper)
    const Eigen::VectorXd& speeds() const { return *speed_; }                ///< m/s
    const Eigen::VectorXd& angles() const { return *angle_; }                ///< degrees, SUMO's: 0 = north, clockwise
    const Eigen::VectorXd& accelerations() const { return *acceleration_; }  ///< m/s²
    const Eigen::VectorXd& lengths() const { return *length_; }              ///< m
    const Eigen::VectorXd& widths() const { return *width_; }                ///< m
    const Eigen::VectorXd& maxSpeeds() const { return *maxSpeed_; }          ///< m/s, the vehicle's own cap
    /// The same arrays, for a reader that keeps them past the step (a Python service's numpy
    /// view): the next refill writes elsewhere while they are held, so they keep this step's values.
    std::shared_ptr<const Eigen::Matrix2Xd> sharedPositions() const { return position_.shared(); }
    std::shared_ptr<const Eigen::VectorXd> sharedSpeeds() const { return speed_.shared(); }
    std::shared_ptr<const Eigen::VectorXd> sharedAngles() const { return angle_.shared(); }
    std::shared_ptr<const Eigen::VectorXd> sharedAccelerations() const { return acceleration_.shared(); }
    std::shared_ptr<const Eigen::VectorXd> sharedLengths() const { return length_.shared(); }
    std::shared_ptr<const Eigen::VectorXd> sharedWidths() const { return width_.shared(); }

    const std::string& roadId(Index i) const { return strings_[road_[i]]; }
    const std::string& laneId(Index i) const { return strings_[lane_[i]]; }
    /// The vehicle type it departed with (SUMO's own copy "<type>@<id>", made when a command
    /// changes one vehicle, is not reported).
    const std::string& typeId(Index i) const { return strings_[type_[i]]; }

    /// The interned index of roadId(i) / laneId(i) / typeId(i): equal keys, equal strings. Lets a
    /// condition on strings decide once per distinct string instead of once per vehicle.
    std::int32_t roadKey(Index i) const { return road_[i]; }
    std::int32_t laneKey(Index i) const { return lane_[i]; }
    std::int32_t typeKey(Index i) const { return type_[i]; }
    /// The interned strings by key. Filled step after step the table only grows, so a key keeps
    /// its string for as long as internGeneration() stays the same (assign() starts a new one).
    const std::vector<std::string>& interned() const { return strings_; }
    std::uint64_t internGeneration() const { return generation_; }

    /// One vehicle's values, for building a snapshot by hand (tests, tools); SUMO runs fill it directly.
    struct Vehicle {
        std::string id;
        double x = 0, y = 0, speed = 0, angle = 0, acceleration = 0;
        double length = 5, width = 1.8, maxSpeed = 50;
        std::string road, lane, type = "car";
    };
    /// Replaces the content with `vehicles` (any order; stored in ascending id order) at `time`.
    void assign(std::vector<Vehicle> vehicles, kernel::SimTime time);
    /// Replaces the content with the vehicles of `from` at the ascending indices `keep`, with the
    /// same interned keys (a view of some vehicles, e.g. the equipped ones). `from` must not be this.
    void assignSubset(const VehicleSnapshot& from, const std::vector<Index>& keep);

private:
    friend class SnapshotBuilder;

    kernel::SimTime time_;
    SnapshotColumns columns_ = SnapshotColumns::all();
    std::vector<std::string> ids_;
    // Shared so that a Python view can point at a step's values and keep them (SharedColumn).
    SharedColumn<Eigen::Matrix2Xd> position_;
    SharedColumn<Eigen::VectorXd> speed_, angle_, acceleration_, length_, width_, maxSpeed_;
    std::vector<std::int32_t> road_, lane_, type_;  // indices into strings_
    std::vector<std::string> strings_;              // interned road, lane and type ids
    std::uint64_t generation_ = nextGeneration();   // unique per string table, process-wide
    std::uint64_t idsVersion_ = nextGeneration();   // unique per id list, process-wide

    static std::uint64_t nextGeneration();
};

}  // namespace sbsim::traffic
