#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/channel/ChannelAccess.h"
#include "sbsim/radio/channel/ChannelSettings.h"
#include "sbsim/radio/channel/ChannelStations.h"
#include "sbsim/radio/channel/Link.h"
#include "sbsim/radio/channel/LinkBudget.h"
#include "sbsim/radio/channel/LoadMonitor.h"
#include "sbsim/radio/channel/Reception.h"
#include "sbsim/radio/propagation/Obstacles.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::radio {

/// IEEE 802.11p broadcast at packet level (see ChannelSettings for every parameter):
///  - each station queues its frames and contends for the channel with CSMA/CA (AIFS, then a
///    backoff of 13 µs slots counted down only while it senses the channel idle; no ACKs):
///    ChannelAccess;
///  - a transmission starts and ends as kernel events; at its start the received power at every
///    station within the cutoff range is computed once (path loss, obstacles, log-normal
///    shadowing, optional Nakagami fading) from the last SUMO snapshot's positions: LinkBudget;
///  - a station senses the channel busy while the power it receives is at or above the sensing
///    threshold; it locks onto the first frame it detects, does not receive while transmitting,
///    and decodes with probability 1 − FER(SINR) where the interference is the largest sum of the
///    other overlapping frames during this one: Reception;
///  - per station a channel busy ratio every 100 ms feeds ETSI reactive DCC: LoadMonitor.
/// The medium wires these parts (each owns its per-station arrays, by the slot of
/// ChannelStations): it keeps the stations' positions, puts frames on the air and ends them,
/// and delivers, counts and traces the receptions.
/// Every random draw is keyed by (seed, sender, sequence, receiver, purpose) (CounterRandom),
/// and link powers are computed on the kernel's pool, so results do not depend on the thread count.
class SBSIM_API ChannelMedium : public Medium, private ChannelAccess::Clock, private Reception::Listener {
public:
    /// Throws std::invalid_argument if a setting is out of range.
    ChannelMedium(ChannelSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory,
                  std::shared_ptr<const Obstacles> obstacles = {});
    ~ChannelMedium() override;

    const ChannelSettings& settings() const { return settings_; }
    /// Links longer than this are not computed (ChannelSettings::interferenceFloorDbm).
    double cutoffRange() const { return budget_.cutoffRange(); }
    /// Where the far tier's cells begin (ChannelSettings::farCellM), 0 without it.
    double farRange() const { return budget_.farRange(); }
    /// The mean received power (dBm) at `distance` m without obstacles, shadowing or fading.
    double meanPowerDbm(double distance) const { return budget_.meanPowerDbm(distance); }

    void initialize() override;
    void handleMessage(kernel::Message& msg) override;
    void broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message) override;
    std::optional<kernel::SimTime> dccInterval(const std::string& station) const override;
    std::optional<double> channelBusyRatio(const std::string& station) const override;
    std::optional<LoadFigures> loadFigures() const override { return load_.figures(); }
    std::optional<LinkFigures> linkFigures() const override { return budget_.tiers(); }

    /// Figures for tests and benchmarks.
    std::uint64_t transmissions() const { return transmissions_; }
    std::uint64_t receptions() const { return receptions_; }

private:
    struct Transmission;
    struct EndTimer;
    using Slot = ChannelStations::Slot;

    void refreshStations();
    Slot stationOf(const std::string& id);
    void startTransmission(Slot s);
    void endTransmission(std::uint64_t id);
    // Reception::Listener
    void channelSensed(Slot s, bool busy) override;
    void setCbrBusy(Slot s);
    void traceLost(const Transmission& tx, Slot receiver, double distance, LossReason reason);
    // ChannelAccess::Clock
    kernel::SimTime now() const override { return simTime(); }
    void schedule(kernel::SimTime at, kernel::Message& timer) override { scheduleAt(at, timer); }
    void cancel(kernel::Message& timer) override { cancelEvent(timer); }

    ChannelSettings settings_;
    const traffic::VehicleSnapshot& snapshot_;
    std::uint64_t seed_ = 0;
    // The parts, each with its per-station arrays by slot.
    ChannelStations stations_;
    Reception reception_;  // before the budget: the settings are checked as it is built
    LinkBudget budget_;
    std::vector<Slot> dccChanged_;  // the last load sample's

    std::unordered_map<std::uint64_t, std::unique_ptr<Transmission>> active_;
    /// Ended transmissions kept for reuse: their link vectors stay allocated and warm in the cache
    /// (a fresh vector per frame cost page faults and cache misses on every link written).
    std::vector<std::unique_ptr<Transmission>> spare_;
    std::uint64_t nextTx_ = 1;
    std::unique_ptr<kernel::Message> loadTimer_;
    ChannelAccess access_;
    LoadMonitor load_;
    std::uint64_t transmissions_ = 0, receptions_ = 0;
};

}  // namespace sbsim::radio
