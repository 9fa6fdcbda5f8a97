#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "sbsim/kernel/ParallelFor.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/FixedStations.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/channel/ChannelSettings.h"
#include "sbsim/radio/channel/ChannelStations.h"
#include "sbsim/radio/channel/FarCells.h"
#include "sbsim/radio/channel/Link.h"
#include "sbsim/radio/channel/PairLosses.h"
#include "sbsim/radio/channel/StepLinks.h"
#include "sbsim/radio/propagation/CorrelatedShadowing.h"
#include "sbsim/radio/propagation/NakagamiFading.h"
#include "sbsim/radio/propagation/Obstacles.h"
#include "sbsim/radio/propagation/PathLoss.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::radio {

/// The received power of every link of a frame, in tiers (ChannelSettings::linkTiers), cheapest
/// first as Veins thresholds: the mean power — path loss and obstacles, the same for all of a
/// sender's frames in one SUMO step, so kept per sender and step — decides whether a link is
/// skipped (below the interference floor by the cutoff's margin), interference only (below the
/// sensing threshold by a margin: its mean power, no draw) or drawn in full: log-normal shadowing
/// — per pair of stations, correlated over the distance they moved (CorrelatedShadowing), or drawn
/// per link and frame with a correlation distance of 0 — and optional Nakagami fading drawn per
/// link and frame. Per station its neighbourhood for the step, struct-of-arrays by slot.
class LinkBudget {
public:
    using Slot = ChannelStations::Slot;

    /// Throws std::invalid_argument for a setting out of range. The references must outlive this.
    LinkBudget(const ChannelSettings& settings, std::shared_ptr<const Obstacles> obstacles,
               const ChannelStations& stations, const traffic::VehicleSnapshot& snapshot, const FixedStations& fixed);

    /// Links longer than this are not computed (ChannelSettings::interferenceFloorDbm).
    double cutoffRange() const { return cutoff_; }
    /// Where the far tier begins (ChannelSettings::farCellM), 0 without it.
    double farRange() const { return far_ ? farRange_ : 0.0; }
    /// The far tier's cells of the step, null without it.
    const FarCells* farCells() const { return far_ ? &cells_ : nullptr; }
    /// The mean received power (dBm) at `distance` m without obstacles, shadowing or fading.
    double meanPowerDbm(double distance) const;

    /// The run starts with seed `seed` (the correlated shadowing's draws).
    void start(std::uint64_t seed);
    /// Forgets the shadowing of pairs unseen for a while (every load sample).
    void forget(kernel::SimTime now);
    /// A new station, slot size().
    void addStation();
    /// The stations were refreshed for a new snapshot: neighbourhoods of stations that left are
    /// dropped (a long run sees tens of thousands of vehicles), the grid is built anew.
    void newStep();
    /// The links of the frame of `sender` keyed `frameKey` (CounterRandom::frameKey), sent at
    /// `now`: the sender's links of the step, and in `drawn` those drawn for this frame (in the
    /// step's order), computed on `pool`: the same whatever its thread count.
    std::shared_ptr<const StepLinks> computeLinks(Slot sender, std::uint64_t frameKey, kernel::SimTime now,
                                                  std::vector<Link>& drawn, kernel::ParallelFor& pool);
    /// Links per tier over the run: drawn in full, interference only, skipped below the floor.
    const Medium::LinkFigures& tiers() const { return tiers_; }

private:
    /// A sender's receivers within the cutoff and their links for one step.
    struct Neighbourhood {
        std::optional<kernel::SimTime> at;   // the snapshot they were computed for
        std::vector<Slot> candidates;        // the grid's answer, until classify()
        std::size_t farTested = 0;           // the leading candidates already not in a far cell
        bool obstaclesPending = false;       // candidates found, the buildings' loss not yet walked
        std::vector<double> obstacleDb;      // per candidate, the buildings' loss
        std::shared_ptr<StepLinks> links;    // shared with the frames on the air
        std::vector<std::uint32_t> full;     // the links drawn per frame (every one without tiers)
        std::vector<std::uint64_t> fullKey;  // their receivers' keys, contiguous
        std::vector<double> fullMeanDbm;     // their mean power
        void resizeFull(std::size_t n) {
            full.resize(n);
            fullKey.resize(n);
            fullMeanDbm.resize(n);
        }
        std::uint64_t skipped = 0;  // within the cutoff but below the floor (obstacles)
        /// The full links' shadowing pairs, looked up at the step's first frame (a generation of
        /// CorrelatedShadowing: a sweep that freed pairs makes them stale).
        std::vector<CorrelatedShadowing::Index> pair;
        std::vector<std::uint64_t> pairKeys;  // the receivers `pair` is for (the last step's)
        std::vector<CorrelatedShadowing::Index> scratch;
        std::optional<kernel::SimTime> pairsAt;
        std::uint64_t pairsGeneration = 0;
    };
    void prepareStep(Slot first, kernel::ParallelFor& pool);
    /// near.pair for near.fullKey: the last step's index of a receiver still near where it was in
    /// the list, else a lookup (the table is a cache miss per pair; between two 0.1 s steps a
    /// sender's receivers barely change).
    void findPairs(Slot s, Neighbourhood& near, kernel::SimTime now);
    /// Fills near_[s] for the current step; touches nothing else, so distinct stations may be
    /// computed on distinct threads.
    void computeNeighbourhood(Slot s);
    /// Walks near_[s]'s links through the buildings (its links spread over `pool`), then classify().
    void applyObstacles(Slot s, kernel::ParallelFor& pool);
    /// near_[s]'s links and their tiers from its candidates (and their buildings' loss).
    void classify(Slot s);

    const ChannelSettings& settings_;
    std::shared_ptr<const Obstacles> obstacles_;
    const ChannelStations& stations_;
    const traffic::VehicleSnapshot& snapshot_;
    const FixedStations& fixed_;
    std::unique_ptr<PathLoss> pathLoss_;
    NakagamiFading fading_;
    std::unique_ptr<CorrelatedShadowing> shadowing_;  // null: drawn per frame
    double cutoff_ = 0;
    double floorMarginDb_ = 0;  // the cutoff's margin for shadowing and fading
    double meanGainDb_ = 0;     // shadowing's linear mean, in dB: σ² ln10 / 20
    double floorMw_ = 0;        // Reception's floor: an interference-only link below it adds nothing
    bool far_ = false;          // the far tier (ChannelSettings::farCellM) is on
    double farRange_ = 0;       // beyond it every link is interference only and untraced
    FarCells cells_;

    std::vector<Neighbourhood> near_;
    std::optional<kernel::SimTime> batchedAt_;  // the step prepareStep() ran for
    std::uint64_t step_ = 0;                    // counts prepareStep() calls
    std::vector<std::uint64_t> sentInStep_;     // per slot, the step_ of its last frame
    std::vector<Slot> sentThisStep_, batch_;
    traffic::NeighbourGrid grid_;
    Medium::LinkFigures tiers_;
    // The buildings' loss per pair of slots within the step obstacleStep_ (the same both ways).
    PairLosses obstacleDb_;
    std::uint64_t obstacleStep_ = 0;
    std::vector<std::size_t> obstacleTodo_;
};

}  // namespace sbsim::radio
