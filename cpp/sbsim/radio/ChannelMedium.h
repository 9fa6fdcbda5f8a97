#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/ChannelSettings.h"
#include "sbsim/radio/DccStateMachine.h"
#include "sbsim/radio/FrameErrorTable.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/NakagamiFading.h"
#include "sbsim/radio/Obstacles.h"
#include "sbsim/radio/PathLoss.h"
#include "sbsim/radio/propagation/CorrelatedShadowing.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::radio {

/// IEEE 802.11p broadcast at packet level (see ChannelSettings for every parameter):
///  - each station queues its frames and contends for the channel with CSMA/CA (AIFS, then a
///    backoff of 13 µs slots counted down only while it senses the channel idle; no ACKs);
///  - a transmission starts and ends as kernel events; at its start the received power at every
///    station within the cutoff range is computed once (path loss, obstacles, log-normal
///    shadowing per pair correlated over the distance moved or drawn per frame, optional Nakagami
///    fading) from the last SUMO snapshot's positions;
///  - a station senses the channel busy while the power it receives is at or above the sensing
///    threshold; it locks onto the first frame it detects, does not receive while transmitting,
///    and decodes with probability 1 − FER(SINR) where the interference is the largest sum of the
///    other overlapping frames during this one;
///  - per station a channel busy ratio every 100 ms feeds ETSI reactive DCC (DccStateMachine).
/// Every random draw is keyed by (seed, sender, sequence, receiver, purpose) (CounterRandom), a
/// correlated shadowing update by (seed, pair, update count) (CorrelatedShadowing),
/// and link powers are computed on the kernel's pool, so results do not depend on the thread count.
class SBSIM_API ChannelMedium : public Medium {
public:
    /// Throws std::invalid_argument if a setting is out of range.
    ChannelMedium(ChannelSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory,
                  std::shared_ptr<const Obstacles> obstacles = {});
    ~ChannelMedium() override;

    const ChannelSettings& settings() const { return settings_; }
    /// Links longer than this are not computed (ChannelSettings::interferenceFloorDbm).
    double cutoffRange() const { return cutoff_; }
    /// The mean received power (dBm) at `distance` m without obstacles, shadowing or fading.
    double meanPowerDbm(double distance) const;

    void initialize() override;
    void handleMessage(kernel::Message& msg) override;
    void broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message) override;
    std::optional<kernel::SimTime> dccInterval(const std::string& station) const override;
    std::optional<double> channelBusyRatio(const std::string& station) const override;
    std::optional<LoadFigures> loadFigures() const override { return load_; }

    /// Figures for tests and benchmarks.
    std::uint64_t transmissions() const { return transmissions_; }
    std::uint64_t receptions() const { return receptions_; }
    std::uint64_t linksComputed() const { return linksComputed_; }

private:
    struct Link;
    struct Transmission;
    struct Incoming {
        Transmission* tx;  // owned by active_ while it is on the air
        std::uint32_t link;
        double mw;
    };
    struct Queued {
        std::shared_ptr<const V2xMessage> message;
    };
    struct StationTimer;
    struct EndTimer;
    using Slot = std::int32_t;

    void refreshStations();
    Slot stationOf(const std::string& id);
    void startAccess(Slot s);
    void scheduleCountdown(Slot s);
    void startTransmission(Slot s);
    void endTransmission(std::uint64_t id);
    void computeLinks(Slot s, const Transmission& tx, std::vector<Link>& links);
    void prepareStep(Slot first);
    /// Fills near_[s] for the current step; touches nothing else, so distinct stations may be
    /// computed on distinct threads.
    void computeNeighbourhood(Slot s);
    void setSensedPower(Slot s, double mw);
    void setCbrBusy(Slot s);
    void sampleLoad();
    void traceLost(const Transmission& tx, Slot receiver, double distance, LossReason reason);

    ChannelSettings settings_;
    const traffic::VehicleSnapshot& snapshot_;
    std::shared_ptr<const Obstacles> obstacles_;
    std::unique_ptr<PathLoss> pathLoss_;
    FrameErrorTable fer_;
    NakagamiFading fading_;
    double cutoff_ = 0;
    double sensingMw_, noiseMw_, floorMw_;
    std::uint64_t seed_ = 0;
    std::unique_ptr<CorrelatedShadowing> shadowing_;  // null: drawn per frame
    std::vector<CorrelatedShadowing::Index> pairs_;   // the current frame's, per link

    // Stations (equipped vehicles), struct-of-arrays by slot; a slot is never reused.
    std::unordered_map<std::string, Slot> slotOf_;
    std::vector<std::string> ids_;
    std::vector<std::uint64_t> keys_;  // CounterRandom::keyOf(id)
    std::vector<double> x_, y_;
    std::vector<std::uint8_t> present_;  // in the last snapshot
    std::vector<double> sensedMw_;
    std::vector<std::uint8_t> sensedBusy_;
    std::vector<std::uint64_t> transmitting_;  // tx id, 0 = none
    std::vector<std::uint64_t> locked_;        // the tx being decoded, 0 = none
    std::vector<std::vector<Incoming>> incoming_;
    std::vector<std::uint8_t> cbrBusy_;
    std::vector<kernel::SimTime> cbrSince_, windowStart_;
    std::vector<kernel::SimTime::rep> busyNs_;
    std::vector<double> cbr_;
    std::vector<DccStateMachine> dcc_;
    std::vector<std::deque<Queued>> queue_;
    std::vector<std::uint8_t> contending_;
    std::vector<std::int32_t> backoff_;  // slots left
    std::vector<kernel::SimTime> countStart_, idleSince_;
    std::vector<std::unique_ptr<StationTimer>> timers_;
    /// A sender's receivers within the cutoff and their distance and mean power, for one step.
    struct Neighbourhood {
        std::optional<kernel::SimTime> at;  // the snapshot they were computed for
        std::vector<Slot> receivers;
        std::vector<double> distance, meanDbm;
        std::vector<std::uint64_t> key;  // the receivers' CounterRandom keys, contiguous
        std::vector<std::uint32_t> bin;  // distance / kDistanceBin
    };
    std::vector<Neighbourhood> near_;
    std::optional<kernel::SimTime> batchedAt_;  // the step prepareStep() ran for
    std::uint64_t step_ = 0;                    // counts prepareStep() calls
    std::vector<std::uint64_t> sentInStep_;     // per slot, the step_ of its last frame
    std::vector<Slot> sentThisStep_, batch_;
    std::vector<Receiver*> receiver_;  // the station's receiving side as of the last step; null: gone

    std::optional<kernel::SimTime> refreshedAt_;
    std::vector<Slot> slotOfIndex_;  // per snapshot index, -1 = not a station
    traffic::NeighbourGrid grid_;

    std::unordered_map<std::uint64_t, std::unique_ptr<Transmission>> active_;
    /// Ended transmissions kept for reuse: their link vectors stay allocated and warm in the cache
    /// (a fresh vector per frame cost page faults and cache misses on every link written).
    std::vector<std::unique_ptr<Transmission>> spare_;
    std::uint64_t nextTx_ = 1;
    std::unique_ptr<kernel::Message> loadTimer_;
    std::optional<LoadFigures> load_;
    double cbrSum_ = 0;
    std::uint64_t transmissions_ = 0, receptions_ = 0, linksComputed_ = 0;
};

}  // namespace sbsim::radio
