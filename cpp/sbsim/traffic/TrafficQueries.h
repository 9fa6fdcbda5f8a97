#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

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

    virtual ~TrafficQueries() = default;
    /// The vehicle ahead of `vehicle` on its route within `lookAhead` m, if any.
    virtual std::optional<Leader> leader(const std::string& vehicle, double lookAhead) = 0;
    /// The collisions of the step that ended at `now` (asked of SUMO once per step).
    virtual const std::vector<Collision>& collisions(kernel::SimTime now) = 0;
};

/// TrafficQueries answered by libsumo (a loaded SUMO).
class SBSIM_API SumoQueries : public TrafficQueries {
public:
    std::optional<Leader> leader(const std::string& vehicle, double lookAhead) override;
    const std::vector<Collision>& collisions(kernel::SimTime now) override;

private:
    std::optional<kernel::SimTime> collisionsAt_;
    std::vector<Collision> collisions_;
};

}  // namespace sbsim::traffic
