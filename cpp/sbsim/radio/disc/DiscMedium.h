#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/DefaultInitAllocator.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/RandomStream.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/disc/DiscSettings.h"
#include "sbsim/radio/disc/KeptNeighbourhoods.h"
#include "sbsim/radio/disc/SquaredDistanceBins.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::radio {

/// Single-hop broadcast on an ideal disc: a message reaches every other station within range
/// (positions of the current step, found through a neighbour grid, not all pairs) after the
/// latency, unless the packet-error model drops it.
class SBSIM_API DiscMedium : public Medium {
public:
    DiscMedium(DiscSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory);

    const DiscSettings& settings() const { return settings_; }
    /// Probability that a message sent `distance` metres away is received.
    double receptionProbability(double distance) const;

    void initialize() override;
    void broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message) override;

private:
    DiscSettings settings_;
    SquaredDistanceBins bins_;  // of settings_.range
    const traffic::VehicleSnapshot& snapshot_;
    /// The step's grid, for a roadside unit's neighbours, and a vehicle's while kept lists do not
    /// pay (built when first needed in a step).
    traffic::NeighbourGrid grid_;
    bool gridBuilt_ = false;
    /// A grid query's scratch: its answer as a bit set and the squared distances, per snapshot index.
    std::vector<std::uint64_t> marks_;
    std::vector<double, kernel::DefaultInitAllocator<double>> squared_;
    std::optional<kernel::SimTime> gridTime_;  // the snapshot time of step_
    std::uint64_t step_ = 0;                   // counts the snapshot's steps seen
    /// A vehicle's neighbours, from lists kept across steps (for one radius: the range, or the
    /// trace range with a trace), updated at a step's first frame.
    std::optional<KeptNeighbourhoods> kept_;
    std::uint64_t keptStep_ = 0;
    std::uint64_t keptIdsVersion_ = 0;
    /// Per snapshot index, the station's receiving side, looked up once per step (while no
    /// module joins or leaves; null if not a station), with its stationIndex(): one record a
    /// link reads. Empty: to be set afresh.
    struct Slot {
        Receiver* receiver = nullptr;
        StationIndex station = 0;
        bool known = false;
    };
    std::vector<Slot> slots_;
    /// Per snapshot index, the station's stationIndex(), interned in the snapshot's order when the
    /// step's grid is built (so a frame's receivers come in ascending indices, as the certificate
    /// policy's tables are sorted); per stationary station, the same.
    std::vector<StationIndex> stationIndices_;
    std::vector<StationIndex> previousIndices_;  // stationIndices_ before the ids last changed
    std::uint64_t idsVersion_ = 0;               // the snapshot's idsVersion() that stationIndices_ follow
    /// Per stationIndex(), its vehicle's snapshot index, or kNotInSnapshot.
    std::vector<traffic::VehicleSnapshot::Index> snapshotIndices_;
    static constexpr auto kNotInSnapshot = static_cast<traffic::VehicleSnapshot::Index>(-1);
    std::vector<StationIndex> fixedIndices_;
    std::uint64_t receiversChanges_ = 0;
    /// Per sender's stationIndex(), the stations within the visit radius and their squared
    /// distances (the neighbour test's own: the root is the bits of the positions' difference's
    /// norm()), computed at the sender's first frame of a step and reused by its others (a beacon
    /// sends several).
    struct Neighbourhood {
        std::uint64_t step = 0;  // step_ of `others`; 0: none
        double radius = 0;
        KeptNeighbourhoods::Indices others;
        KeptNeighbourhoods::Squares squared;
        /// Without packet errors or a trace every station in range receives: the stations in
        /// range (receivers, their indices, in the order above) and their count per distance bin,
        /// taken once per step and module change, so a frame copies them instead of visiting each link.
        bool receiversKnown = false;
        std::uint64_t receiversChanges = 0;
        /// Shared with the frames on the air and held by the certificate policy as the sender's
        /// last list: kept from step to step while the receivers stay the same, so the policy
        /// finds the list it holds and walks nothing.
        std::shared_ptr<Recipients> recipients;
        std::vector<std::uint64_t> perBin;
    };
    /// The step's grid_, once per step.
    void buildGrid();
    /// `near`'s receivers in range (of `sender`, near_[sender]), as of the current modules.
    void takeReceivers(StationIndex sender, Neighbourhood& near);
    std::vector<Neighbourhood> near_;
    Recipients scratch_;                            // takeReceivers' new list, compared with the last
    std::shared_ptr<kernel::RandomStream> random_;  // the simulation's, taken at initialize()
};

}  // namespace sbsim::radio
