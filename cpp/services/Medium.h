#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/RandomStream.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::services {

class Middleware;
class V2xMessage;

struct SBSIM_API MediumSettings {
    double range = 500;  ///< m
    kernel::SimTime latency = kernel::SimTime::fromMilliseconds(1);
    /// Packet errors: reception is certain up to this distance, then falls linearly to 0 at
    /// `range`. None (the default): no losses.
    std::optional<double> fadeStart;
};

/// Single-hop broadcast between vehicles: a message reaches the middleware of every other vehicle
/// within range (positions of the current step, found through a neighbour grid, not all pairs)
/// after the latency, unless the packet-error model drops it. Counts messages per type.
class SBSIM_API Medium : public kernel::Module {
public:
    struct Counts {
        std::uint64_t sent = 0;
        std::uint64_t delivered = 0;
    };
    using Directory = std::function<Middleware*(const std::string& vehicleId)>;

    Medium(MediumSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory);

    const MediumSettings& settings() const { return settings_; }
    /// Probability that a message sent `distance` metres away is received.
    double receptionProbability(double distance) const;

    void initialize() override;

    void broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message);
    /// Called by a middleware when a message reaches it.
    void delivered(const V2xMessage& message);

    const std::map<std::string, Counts, std::less<>>& counts() const { return counts_; }

private:
    MediumSettings settings_;
    const traffic::VehicleSnapshot& snapshot_;
    Directory directory_;
    traffic::NeighbourGrid grid_;
    std::optional<kernel::SimTime> gridTime_;
    std::shared_ptr<kernel::RandomStream> random_;  // the simulation's, taken at initialize()
    std::map<std::string, Counts, std::less<>> counts_;
};

}  // namespace sbsim::services
