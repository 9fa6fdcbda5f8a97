#pragma once

#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/geometry/Polygon.h"

namespace sbsim::storyboard {

/// Passes when every vehicle that reached the place (an area, or an edge) had heard a DENM of
/// `cause` (any if none) at least `lead` before: its DENM memory (facilities::DenmMemory, as the
/// stations registry keeps it) held such an event first heard no later than the reach time minus
/// `lead`. A vehicle reaches the place at the first step it is there (front bumper inside the area,
/// or on the edge) after a step it was not: vehicles that depart there are not judged, nor those
/// reaching it outside [since, until] (before the hazard, after it cleared), nor an event's
/// originator (the warning's sender); with `equippedOnly`, nor the vehicles without V2X equipment
/// (EvaluationContext::equipped), which could never hear one. The DENM memory is what a DEN
/// service fills: a run without one refuses it.
class WarnedBefore : public Criterion {
public:
    /// Throws std::invalid_argument for a negative lead, a cause outside 0..255, or until < since.
    static std::shared_ptr<WarnedBefore> inArea(geometry::Polygon area, std::optional<int> cause, kernel::SimTime lead,
                                                kernel::SimTime since, std::optional<kernel::SimTime> until,
                                                bool equippedOnly = false);
    static std::shared_ptr<WarnedBefore> onEdge(std::string edge, std::optional<int> cause, kernel::SimTime lead,
                                                kernel::SimTime since, std::optional<kernel::SimTime> until,
                                                bool equippedOnly = false);

    std::string describe() const override;
    traffic::SnapshotColumns columns() const override;
    bool readsDenmMemory() const override { return true; }
    void check(CheckContext& ctx) const override;
    void observe(const EvaluationContext& ctx) override;
    CriterionVerdict verdict(const CriterionRun& run) const override;

private:
    WarnedBefore(std::optional<geometry::Polygon> area, std::string edge, std::optional<int> cause,
                 kernel::SimTime lead, kernel::SimTime since, std::optional<kernel::SimTime> until, bool equippedOnly);
    bool there(const traffic::VehicleSnapshot& s, traffic::VehicleSnapshot::Index i) const;
    /// The first time `id` heard a matching DENM, from what its memory holds now.
    std::optional<kernel::SimTime> heard(const EvaluationContext& ctx, const std::string& id);

    struct Track {
        bool wasAway = false;  ///< seen away from the place at some step
        bool decided = false;  ///< reached it (judged or not): nothing more to watch
        std::optional<kernel::SimTime> warnedAt;
    };
    struct Reach {
        std::string vehicle;
        kernel::SimTime at;
        std::optional<kernel::SimTime> warnedAt;
    };

    std::optional<geometry::Polygon> area_;
    std::string edge_;  // when no area
    std::optional<int> cause_;
    kernel::SimTime lead_, since_;
    std::optional<kernel::SimTime> until_;
    bool equippedOnly_;
    std::unordered_map<std::string, Track> tracks_;  // the running vehicles
    std::vector<Reach> reached_;                     // judged, in order of reaching
    std::set<std::string> originators_;              // of the matching events heard
};

}  // namespace sbsim::storyboard
