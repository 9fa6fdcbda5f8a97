#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/V2xMessage.h"
#include "sbsim/radio/geonet/CbfTimeout.h"
#include "sbsim/radio/geonet/DuplicatePacketList.h"
#include "sbsim/radio/geonet/GreedyForwarding.h"
#include "sbsim/radio/geonet/PacketHeader.h"

namespace sbsim::radio::geonet {

/// How a station's router handles geo-broadcasts.
struct SBSIM_API RouterSettings {
    /// Off: a geo-broadcast goes one hop, as one broadcast that receivers outside its area drop
    /// (sbsim without GeoNetworking's forwarding).
    bool forwarding = true;
    std::uint8_t hopLimit = PacketHeader::kDefaultHopLimit;  ///< a new packet's hop limit
    CbfTimeout cbf;
};

/// One station's GeoNetworking router (EN 302 636-4-1, the parts Vanetza's Router runs for GBC
/// with its default MIB: area forwarding CBF, non-area forwarding greedy), without the kernel:
/// the station sends what originate() stamped, hands each received frame to receive(), sends
/// what it returns to send at once, and at nextTimeout() sends what takeExpired() gives.
///
/// - Source: a geo-broadcast gets this station as source, its next sequence number and the hop
///   limit; sent from inside its area it is a broadcast, from outside a unicast to the neighbour
///   with the most progress towards the area's centre (a broadcast at a local optimum, as the
///   standard without store-carry-forward).
/// - Receiver: a frame unicast to another station is dropped (the MAC would); a packet seen
///   before (duplicate list by source and sequence number) is dropped, and cancels this station's
///   contending copy of it. A new one is passed up when the station is inside the area; with hop
///   limit left it is forwarded: inside the area through contention-based forwarding (buffered,
///   rebroadcast after the CBF timeout unless a duplicate is heard first), outside greedily at
///   once, unless it came from a station inside the area (area broadcasts stay in the area).
class SBSIM_API Router {
public:
    /// The station's neighbours; asked only when greedy forwarding needs them.
    using Neighbours = std::function<std::vector<Neighbour>()>;

    struct Reception {
        bool passUp = false;                     ///< to the facilities and services
        std::unique_ptr<V2xMessage> forwardNow;  ///< greedy forwarding: send this now
        bool timersChanged = false;              ///< nextTimeout() may differ
    };

    Router(std::string station, RouterSettings settings = {});

    const RouterSettings& settings() const { return settings_; }
    /// Source operations on `message`, about to be sent from `position`.
    void originate(V2xMessage& message, const Eigen::Vector2d& position, const Neighbours& neighbours);
    /// Receiver and forwarder operations on a frame heard at `position` at `now`.
    Reception receive(const V2xMessage& message, const Eigen::Vector2d& position, kernel::SimTime now,
                      const Neighbours& neighbours);
    /// When the earliest contending packet's CBF timer fires; none while none contends.
    std::optional<kernel::SimTime> nextTimeout() const;
    /// The packets whose timer fired at or before `now`, in firing order, ready to rebroadcast
    /// from `position` (the hop limit already decremented).
    std::vector<std::unique_ptr<V2xMessage>> takeExpired(kernel::SimTime now, const Eigen::Vector2d& position);
    /// Whether a copy of `id` waits for its CBF timer here.
    bool contending(const PacketId& id) const;
    std::size_t contending() const { return buffer_.size(); }

private:
    static PacketHeader& header(V2xMessage& message) { return message.geonet_; }
    /// A copy of `message` to forward, with one hop less; null if the message cannot be copied.
    static std::unique_ptr<V2xMessage> forwardCopy(const V2xMessage& message);
    bool cancel(const PacketId& id);

    struct Contending {
        kernel::SimTime due;
        std::uint64_t order;  // ties fire in the order the packets came
        PacketId id;
        std::unique_ptr<V2xMessage> packet;
    };
    std::string station_;
    RouterSettings settings_;
    std::uint16_t nextSequence_ = 0;
    std::uint64_t nextOrder_ = 0;
    DuplicatePacketList duplicates_;
    std::vector<Contending> buffer_;  // a few packets at most: a plain vector
};

}  // namespace sbsim::radio::geonet
