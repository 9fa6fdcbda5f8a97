#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/traffic/NetworkController.h"
#include "sbsim/traffic/SignalLinks.h"

namespace sbsim::traffic {

/// Values the per-step snapshot lacks, asked of SUMO only for the vehicles (and steps) that need
/// them. Virtual so that tests can stand a model in for SUMO; SumoQueries asks libsumo. Call from
/// one thread.
class SBSIM_API TrafficQueries {
public:
    struct Leader {
        std::string id;
        double gap = 0;  ///< m, the ego's front bumper to the leader's back bumper
    };
    /// The two parties of one collision SUMO reported for the last step.
    struct Collision {
        std::string collider;
        std::string victim;
    };
    /// A traffic light's stop line that a vehicle passed, and its link's state now.
    struct SignalPassage {
        SignalLinks::Link link;
        /// SUMO's link state: 'r' red, 'u' red-yellow, 'y'/'Y' yellow, 'g'/'G' green, 's' stop then
        /// go (green right-turn arrow), 'o'/'O' off.
        char state = 'O';
    };

    virtual ~TrafficQueries() = default;
    /// The vehicle ahead of `vehicle` on its route within `lookAhead` m, if any.
    virtual std::optional<Leader> leader(const std::string& vehicle, double lookAhead) = 0;
    /// The collisions of the step that ended at `now` (asked of SUMO once per step).
    virtual const std::vector<Collision>& collisions(kernel::SimTime now) = 0;
    /// Whether `vehicle`, on lane `from` after the last step and on lane `to` now, passed a
    /// traffic light's stop line in between: the link it used and that link's state now (the
    /// state it moved under: SUMO switches its lights before it moves the vehicles). Ask before
    /// anything else switches a light in this step. A teleport (SUMO moving a vehicle stuck for
    /// --time-to-teleport) passes no line.
    virtual std::optional<SignalPassage> signalPassage(const std::string& vehicle, const std::string& from,
                                                       const std::string& to) = 0;
    /// The distance (m) `vehicle` drove since it departed (SUMO's odometer). Models that do not
    /// answer it throw std::logic_error.
    virtual double odometer(const std::string& vehicle);
    /// A traffic light's state now, one SUMO letter per controlled link (as a story's
    /// TrafficLightEffect or the light's programme set it). Models that do not answer it throw
    /// std::logic_error.
    virtual std::string signalState(const std::string& tls);
};

/// TrafficQueries answered by libsumo (a loaded SUMO).
class SBSIM_API SumoQueries : public TrafficQueries {
public:
    std::optional<Leader> leader(const std::string& vehicle, double lookAhead) override;
    const std::vector<Collision>& collisions(kernel::SimTime now) override;
    std::optional<SignalPassage> signalPassage(const std::string& vehicle, const std::string& from,
                                               const std::string& to) override;
    double odometer(const std::string& vehicle) override;
    /// Asked of libsumo through the NetworkController world effects command lights with.
    std::string signalState(const std::string& tls) override { return network_.signalState(tls); }

private:
    NetworkController network_;
    std::optional<SignalLinks> signals_;  // read at the first question (SUMO is loaded by then)
    std::optional<kernel::SimTime> collisionsAt_;
    std::vector<Collision> collisions_;
};

}  // namespace sbsim::traffic
