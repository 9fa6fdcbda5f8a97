#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <typeinfo>
#include <utility>
#include <vector>

#include "sbsim/kernel/DefaultInitAllocator.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/radio/CertificatePolicy.h"
#include "sbsim/radio/FixedStations.h"
#include "sbsim/radio/MessageTrace.h"
#include "sbsim/radio/ReceptionInterest.h"
#include "sbsim/radio/V2xMessage.h"

namespace sbsim::radio {

class Receiver;

/// What carries V2X messages between stations: a model of the radio channel. A station sends
/// with broadcast(); the medium decides who receives it and when, and hands it to each receiver's
/// module (found through the Directory, a radio::Receiver) at that time: all of a frame's
/// receptions at one time from one kernel event. Counts messages per type.
class SBSIM_API Medium : public kernel::Module {
public:
    struct Counts {
        std::uint64_t sent = 0;
        /// Frames that carried another station's packet on (GeoNetworking forwarding): not in `sent`.
        std::uint64_t forwarded = 0;
        std::uint64_t delivered = 0;
        /// Per 50 m of sender–receiver distance (bin k: [50k, 50k + 50) m): the stations the
        /// medium considered, and those that received the message.
        std::vector<std::uint64_t> linkStations, linkReceptions;
        /// One link of distance bin `bin` (distance / kDistanceBin), received or not. Inline: it runs per link.
        void countLink(std::size_t bin, bool received) {
            if (linkStations.size() <= bin) {
                linkStations.resize(bin + 1);
                linkReceptions.resize(bin + 1);
            }
            ++linkStations[bin];
            if (received) ++linkReceptions[bin];
        }
    };
    static constexpr double kDistanceBin = 50;
    /// A station's index for the run (StationIds), as media hand receivers to deliverLater().
    using StationIndex = StationIds::Index;
    /// A frame's receiving sides, grown without a zero-fill: a medium writes each one it takes.
    using Receivers = std::vector<Receiver*, kernel::DefaultInitAllocator<Receiver*>>;
    /// A frame's receivers (their stationIndex() in `stations`), shareable by the frames of a step.
    struct Recipients {
        Receivers receivers;
        std::vector<StationIndex> stations;
    };
    /// Channel busy ratio over every station's 100 ms samples.
    /// What the link budget did: links drawn in full, interference only (their mean power, no
    /// draw) and skipped below the floor, over the run (ChannelSettings::linkTiers).
    struct LinkFigures {
        std::uint64_t full = 0, interference = 0, skipped = 0;
    };
    struct LoadFigures {
        double meanCbr = 0;
        double maxCbr = 0;
        std::uint64_t samples = 0;
    };
    /// The module a station's receptions go to (its middleware, a radio::Receiver), or none for a
    /// vehicle that is not a station.
    using Directory = std::function<kernel::Module*(const std::string& stationId)>;

    explicit Medium(Directory directory);
    ~Medium() override;

    /// Sends `message` from `sender` (stamped with the sender and the current time).
    virtual void broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message) = 0;
    /// broadcast() by a station that keeps its stationIndex(), `index` (its middleware looks it up
    /// once): the frame's stamp then needs no lookup of the sender's name, a cache miss per frame.
    void broadcastFrom(StationIndex index, const std::string& sender, std::unique_ptr<V2xMessage> message);
    /// `station`'s index for the run (interned on first use): a medium looks it up once per station
    /// and step, and hands deliverLater() indices, not names to copy per reception.
    StationIndex stationIndex(std::string_view station) { return certificates_.index(station); }
    /// The least time between two messages that the channel's congestion control (ETSI DCC)
    /// allows `station` now; none when the medium models no congestion control.
    virtual std::optional<kernel::SimTime> dccInterval(const std::string& /*station*/) const { return std::nullopt; }
    /// The share of the last 100 ms `station` sensed the channel busy; none when the medium does
    /// not model it.
    virtual std::optional<double> channelBusyRatio(const std::string& /*station*/) const { return std::nullopt; }
    /// Mean and max channel busy ratio so far; none when the medium does not model it.
    virtual std::optional<LoadFigures> loadFigures() const { return std::nullopt; }
    virtual std::optional<LinkFigures> linkFigures() const { return std::nullopt; }
    /// Hands a frame's receptions (queued with deliverLater()) to their stations.
    void handleMessage(kernel::Message& msg) override;

    /// Promises that the directory's owner calls stationChanged() for every station whose module it
    /// adds, removes or replaces, from now on: a station's receiving side is then kept across the
    /// run's other module changes (a vehicle's departure elsewhere), not looked up again by name.
    void reportStationChanges();
    /// `stationId`'s module changed (see reportStationChanges()): its receiving side is looked up again.
    void stationChanged(const std::string& stationId);

    const std::map<std::string, Counts, std::less<>>& counts() const { return counts_; }

    /// Makes `id` a stationary station (a roadside unit) at `position`: it sends and receives like a
    /// vehicle of the snapshot, through the directory's module for `id`. Throws
    /// std::invalid_argument for an id already taken, or a position that is not finite.
    void addFixedStation(std::string id, const Eigen::Vector2d& position) { fixed_.add(std::move(id), position); }
    const FixedStations& fixedStations() const { return fixed_; }

    /// Reports every transmission, reception and (within the medium's trace range) loss to
    /// `trace` from now on; null: none. The trace must outlive the run.
    void setTrace(MessageTrace* trace) { trace_ = trace; }
    /// Whether messages are signed (TS 103 097 envelope in their frame size); on by default.
    void setSecured(bool secured) { certificates_.setSecured(secured); }

    /// Which messages `station`'s receiving side is handed: with `types`, only those of these types
    /// (V2xMessage::typeName()), geo-broadcasts (its router forwards them) and the types every
    /// station's own layers take (setLayersTake); without, every message (the default). A reception
    /// it is not handed is still one: counted, traced, its certificate bookkeeping done; only the
    /// station is not visited, as Artery drops a packet for a BTP port no service listens on.
    void setTypesTaken(const std::string& station, const std::optional<std::vector<std::string>>& types) {
        interest_.set(stationIndex(station), types);
    }
    /// Whether every station's own layers take `message`'s type, whatever its services take (the
    /// facilities keep CAMs and DENMs); asked once per message type. Until it is set, every station
    /// is handed every message (setTypesTaken() restricts nothing).
    void setLayersTake(std::function<bool(const V2xMessage&)> layersTake) {
        layersTake_ = std::move(layersTake);
        layersTakeKnown_.clear();
    }

protected:
    /// Stamps `message` as sent by `sender` now, with the sender's next sequence number and its
    /// frame's size (signed now), and counts it.
    void stamp(V2xMessage& message, const std::string& sender);
    /// Counts one station the medium considered for `message` at `distance` m, and whether it received it.
    void countLink(const V2xMessage& message, double distance, bool received);
    /// The counts of `message`'s type (stamped before), to count many links with one lookup.
    Counts* countsOf(const V2xMessage& message);
    static void countLink(Counts& counts, double distance, bool received);
    MessageTrace* trace() const { return trace_; }
    kernel::Module* receiverOf(const std::string& stationId) const { return directory_(stationId); }
    /// The receiving side of `stationId`'s module; null for a vehicle that is not a station. Media
    /// hand deliverLater() only receivers found here (so it knows whether all said what they take).
    Receiver* receivingSide(const std::string& stationId);
    /// The same for `station`, `stationId`'s stationIndex(): kept by index while its module stays,
    /// so a medium asks each step without a lookup by name.
    Receiver* receivingSide(StationIndex station, const std::string& stationId);
    /// Changes when a station found by receivingSide() may have changed: the station changes
    /// reported, else every module change (a medium keeps receivers while it stays the same).
    std::uint64_t receiverChanges() const;
    /// The sender's stationIndex(), as stamp() looked it up.
    static StationIndex senderIndex(const V2xMessage& message) { return message.senderIndex_; }
    /// Delivers `message` to `receivers` (in this order; `stations` are their stationIndex()) after
    /// `delay`, from one kernel event. A station that has left by then is skipped, as its own event
    /// would have been dropped: the pointers are used only while no module joined or left meanwhile,
    /// else the stations are looked up again by name.
    void deliverLater(std::shared_ptr<const V2xMessage> message, Receivers receivers,
                      std::vector<StationIndex> stations, kernel::SimTime delay);
    /// The same with receivers a medium keeps (and may hand several frames) rather than copies. They
    /// must not change while another holder has them (the certificate policy keeps a sender's last
    /// list to know its next frames' receivers unchanged): a medium refills them only when
    /// use_count() is 1.
    void deliverLater(std::shared_ptr<const V2xMessage> message, std::shared_ptr<const Recipients> recipients,
                      kernel::SimTime delay);
    /// The certificate policy, for a medium that hands it how a sender's kept list changed.
    CertificatePolicy& certificates() { return certificates_; }

private:
    /// One frame's receptions at one time: a kernel event the medium keeps and reuses.
    struct FrameDelivery;
    Directory directory_;
    // Every frame delivery made so far, and those not on the air: a frame takes a spare one
    // rather than allocating an event (and its name) and freeing it after delivery.
    std::vector<std::unique_ptr<FrameDelivery>> frames_;
    std::vector<FrameDelivery*> spareFrames_;
    std::map<std::string, Counts, std::less<>> counts_;
    // The counts countsOf() found last and their type's name (a view of their key in counts_).
    Counts* lastCounts_ = nullptr;
    std::string_view lastCountsType_;
    std::vector<std::uint64_t> sequences_;  // next per sender, by station index
    MessageTrace* trace_ = nullptr;
    FixedStations fixed_;
    CertificatePolicy certificates_;
    ReceptionInterest interest_;
    std::function<bool(const V2xMessage&)> layersTake_;
    std::vector<std::pair<const std::type_info*, bool>> layersTakeKnown_;  // layersTake_'s answers per type
    bool everyReceiverRegistered_ = true;  // every receiver found so far called setTypesTaken() first
    // receivingSide() by station index, while receiverChanges() keeps the value it had when filled.
    std::vector<Receiver*> receiverAt_;
    std::vector<unsigned char> receiverKnownAt_;
    std::uint64_t receiversFilledAt_ = 0;
    bool reportsStationChanges_ = false;
    std::uint64_t stationChanges_ = 0;
    // The sender broadcastFrom() named and its index, for the stamp of the frame it is sending.
    const std::string* knownSender_ = nullptr;
    StationIndex knownSenderIndex_ = 0;
    /// Whether `message` goes to every receiver whatever they take.
    bool toEveryReceiver(const V2xMessage& message);
    /// Queues a frame's delivery; `keptByMedium`: the medium may hand the same list to the sender's next frames.
    void queue(std::shared_ptr<const V2xMessage> message, std::shared_ptr<const Recipients> recipients,
               bool keptByMedium, kernel::SimTime delay);
};

}  // namespace sbsim::radio
