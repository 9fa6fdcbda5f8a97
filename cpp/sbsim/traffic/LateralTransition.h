#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/Transition.h"

namespace sbsim::traffic {

/// Where a vehicle is across its road: its lane (from the right, 0-based) and its centre's offset
/// (m, positive to the left) from that lane's centre.
struct SBSIM_API LateralPlace {
    int lane = 0;
    double offset = 0;

    /// Its distance (m) from the road's right edge, for lanes of `widths` (a lane past the road's
    /// last is its last).
    double across(const std::vector<double>& widths) const;
};

/// One lateral manoeuvre along a Transition (OpenSCENARIO's LaneChangeAction and LaneOffsetAction):
/// from where the vehicle is when it starts (its first step) to `target`, which it holds after.
/// Distances across the road are taken on the road the vehicle is on at each step, so a manoeuvre
/// carries on over a junction. The law only: EffectStack commands it through SUMO's sublane model.
class SBSIM_API LateralTransition {
public:
    LateralTransition(Transition dynamics, LateralPlace target) : dynamics_(dynamics), target_(target) {}
    /// Over the time in which `shape` moves the vehicle to `target` with a peak lateral acceleration
    /// of `maxAcceleration` m/s² (OpenSCENARIO's LaneOffsetActionDynamics): cubic 6d/T², sinusoidal
    /// π²d/(2T²) for a move of d m; linear, whose acceleration has no bound, takes cubic's time.
    static LateralTransition withMaxAcceleration(Transition::Shape shape, double maxAcceleration, LateralPlace target);

    /// How far (m, positive to the left) the vehicle should move in the step from `now` to
    /// `now + dt` (s): it is at `place` on a road of lanes `widths`, drives at `speed` m/s, and its
    /// odometer reads `driven` m (read only for a distance dimension). The first call starts it.
    double next(double now, double dt, const LateralPlace& place, const std::vector<double>& widths, double speed,
                double driven);
    bool reached() const { return *reached_; }
    /// reached(), shared by the copies of this transition: the effect that hands it to an
    /// EffectStack keeps this to ask (OpenSCENARIO: its event ends).
    std::shared_ptr<const bool> reachedFlag() const { return reached_; }
    bool needsOdometer() const { return dynamics_.dimension == Transition::Dimension::Distance; }
    const Transition& dynamics() const { return dynamics_; }
    const LateralPlace& target() const { return target_; }

private:
    Transition dynamics_;
    LateralPlace target_;
    bool started_ = false;
    std::shared_ptr<bool> reached_ = std::make_shared<bool>(false);
    std::optional<double> maxAcceleration_;  // m/s²: the time follows at the start
    LateralPlace start_;
    double startTime_ = 0;
    double startDriven_ = 0;
};

}  // namespace sbsim::traffic
