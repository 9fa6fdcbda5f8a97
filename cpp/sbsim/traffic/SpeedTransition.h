#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/Transition.h"

namespace sbsim::traffic {

/// The speed a vehicle should have (OpenSCENARIO's SpeedActionTarget): absolute, or relative to
/// another vehicle's speed (its speed plus `value`, or times `value`), that one read once when the
/// change starts or, `continuous`, every step.
struct SBSIM_API SpeedTarget {
    enum class Kind { Absolute, Delta, Factor };
    Kind kind = Kind::Absolute;
    double value = 0;  ///< m/s (Absolute, Delta) or a factor
    /// The reference vehicle's speed now (m/s); none when it is not running (the last one read stands).
    std::function<std::optional<double>()> reference;
    bool continuous = false;
};

/// One speed change along a Transition, commanded step by step: from the vehicle's speed when it
/// starts (its first step) to the target, which it holds after. The law only: EffectStack commands.
class SBSIM_API SpeedTransition {
public:
    /// `safeGap`: SUMO keeps the vehicle's safe gap to its leader, which also bounds its
    /// acceleration and deceleration to the vehicle's own, so a steep shape comes out flatter;
    /// without it the shape is exact and nothing stops a rear-end collision (as OpenSCENARIO's
    /// actions are executed).
    SpeedTransition(Transition dynamics, SpeedTarget target, bool safeGap = false)
        : dynamics_(dynamics), target_(std::move(target)), safeGap_(safeGap) {}

    /// The speed (m/s) the vehicle should have at the end of the step from `now` to `now + dt` (s);
    /// `speed` is its speed now, `driven` its odometer (m; read only for a distance dimension).
    /// The first call starts the change.
    double next(double now, double dt, double speed, double driven);
    /// Whether the change has run (the target is held from then on).
    bool reached() const { return outcome_->reached; }
    /// Whether it ran and the target it held last, shared by the copies of this transition: the
    /// effect that hands it to an EffectStack keeps this to ask (OpenSCENARIO: its event ends).
    struct Outcome {
        bool reached = false;
        double target = 0;  ///< m/s
    };
    std::shared_ptr<const Outcome> outcome() const { return outcome_; }
    /// The speed mode to command from the vehicle's own `own`: SUMO's bounds on acceleration and
    /// deceleration (bits 1, 2) and, without safeGap, its safe speed (bit 0, which bounds them too)
    /// off; its lane speed limit and speed factor disregarded (bit 6), so the target is the speed.
    int speedMode(int own) const { return (own & ~(safeGap_ ? 0b110 : 0b111)) | 0b1000000; }
    bool safeGap() const { return safeGap_; }
    bool needsOdometer() const { return dynamics_.dimension == Transition::Dimension::Distance; }
    const Transition& dynamics() const { return dynamics_; }

private:
    double target();

    Transition dynamics_;
    SpeedTarget target_;
    bool safeGap_;
    bool started_ = false;
    std::shared_ptr<Outcome> outcome_ = std::make_shared<Outcome>();
    double startTime_ = 0;
    double startSpeed_ = 0;
    double startDriven_ = 0;
    double startDelta_ = 0;  ///< target − start speed when it started (the rate's time)
    double lastTarget_ = 0;
};

}  // namespace sbsim::traffic
