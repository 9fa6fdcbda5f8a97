#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/criteria/VehicleSet.h"

namespace sbsim::storyboard {

/// Passes when no vehicle of the set (all by default) passed a traffic light's stop line on red.
/// Passing the line is what SUMO's junction model decides on: a vehicle leaves a lane that ends at
/// a signal-controlled link for the junction (or beyond) in one step. Red is what SUMO makes a
/// vehicle stop for (MSLink::haveRed): 'r', and 'u' (red-yellow, still red); yellow is not, nor is
/// a green that turned red while the vehicle waited inside the junction (it passed on green), nor
/// a SUMO teleport of a vehicle stuck at the line.
/// Vehicles respecting the lights never fail it; ones told to ignore them (a speed mode without
/// bit 4, a junction model's jmDriveAfterRedTime, a story's effect) do.
class NoRedLightRunning : public Criterion {
public:
    explicit NoRedLightRunning(VehicleSet vehicles) : vehicles_(std::move(vehicles)) {}
    std::string describe() const override { return "NoRedLightRunning(" + vehicles_.argument() + ")"; }
    traffic::SnapshotColumns columns() const override { return traffic::SnapshotColumns::Lane; }
    /// Before the stories: a story switching a light must not change the state the step moved under.
    void prepare(const EvaluationContext& ctx) override;
    CriterionVerdict verdict(const CriterionRun& run) const override;

    /// Whether SUMO's link state `state` is red.
    static bool isRed(char state) { return state == 'r' || state == 'u'; }

private:
    /// The vehicles of the set seen in one step, sorted as the snapshot's ids, with where they were
    /// as the snapshot's interned keys (no string copied or hashed per vehicle and step).
    struct Seen {
        std::vector<std::string> ids;
        std::vector<std::int32_t> road, lane;
        void clear() {
            ids.clear();
            road.clear();
            lane.clear();
        }
    };
    VehicleSet vehicles_;
    Seen last_, now_;  // the last step's vehicles; now_ is this step's, kept for its storage
    // The last step's interned strings, so its keys still name their road and lane should the
    // snapshot start another string table (hand-made snapshots do; a SUMO run's table only grows).
    std::vector<std::string> strings_;
    std::uint64_t generation_ = 0;
    std::size_t passages_ = 0;
    std::unordered_set<std::string> runners_;
    std::vector<std::string> who_;  // runners_ in the order of their first red passage
    std::string first_;             // "a at C1 link 3 at t=12 s"
};

}  // namespace sbsim::storyboard
