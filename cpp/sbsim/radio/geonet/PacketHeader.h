#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/geonet/GeoArea.h"

namespace sbsim::radio::geonet {

/// How a packet travels (EN 302 636-4-1's header types sbsim uses).
enum class Transport : std::uint8_t {
    SingleHop,     ///< SHB: one broadcast, never forwarded (CAMs, beacons, any message by default)
    GeoBroadcast,  ///< GBC: to every station in an area, forwarded towards and inside it (DENMs)
};

/// What makes a packet the same packet at every station it reaches: its source and the source's
/// sequence number (duplicate detection's key).
struct SBSIM_API PacketId {
    std::string source;
    std::uint16_t sequence = 0;
    bool operator==(const PacketId&) const = default;
};

/// The GeoNetworking fields of one transmitted frame, as far as sbsim's routing reads them: the
/// common header's maximum hop limit, the basic header's remaining one, the GBC extended header's
/// source, sequence number and area, the sender's position and the link-layer destination.
struct SBSIM_API PacketHeader {
    /// itsGnDefaultHopLimit, as Vanetza's MIB.
    static constexpr std::uint8_t kDefaultHopLimit = 10;

    Transport transport = Transport::SingleHop;
    GeoArea area;                ///< GBC: the destination area
    std::string source;          ///< the station that made the packet (set when it is first sent)
    std::uint16_t sequence = 0;  ///< the source's GN sequence number (wraps at 2^16, as the field)
    std::uint8_t maxHopLimit = 1;
    std::uint8_t hopLimit = 1;  ///< remaining, as this frame carries it
    /// Where the station transmitting this frame was when it sent it (its position vector).
    Eigen::Vector2d senderPosition = Eigen::Vector2d::Zero();
    /// The link-layer destination: empty for a broadcast, else the one station meant to process
    /// the frame (greedy forwarding's next hop); the others drop it as a MAC filter would.
    std::string nextHop;

    bool geoBroadcast() const { return transport == Transport::GeoBroadcast; }
    /// Transmissions the packet has made up to and including this frame (1: sent by its source).
    unsigned hops() const { return static_cast<unsigned>(maxHopLimit) - hopLimit + 1u; }
    PacketId id() const { return {source, sequence}; }
};

}  // namespace sbsim::radio::geonet
