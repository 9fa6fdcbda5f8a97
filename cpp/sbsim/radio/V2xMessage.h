#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Object.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/FrameSize.h"
#include "sbsim/radio/TraceField.h"
#include "sbsim/radio/geonet/PacketHeader.h"

namespace sbsim::radio {

class Medium;
namespace geonet {
class Router;
}

/// A message one station broadcasts to the stations around it. Subclass it with the content of
/// your application; give it a name (per-type counts in the summary) and a byte size (what it
/// occupies on the channel).
class SBSIM_API V2xMessage : public kernel::Object {
public:
    /// A short type name for statistics, e.g. "ClearLane".
    virtual std::string_view typeName() const = 0;
    virtual std::size_t byteSize() const = 0;
    /// How GeoNetworking carries it, from its GN header (geonet()): single-hop broadcast unless the
    /// message asked for a geo-broadcast (geoBroadcastTo: a DENM). Sets the extended header's size
    /// in frameBytes().
    GnTransport gnTransport() const {
        return geonet_.geoBroadcast() ? GnTransport::GeoBroadcast : GnTransport::SingleHopBroadcast;
    }
    /// Which header its security envelope gets (FrameSize.h): the full certificate every time
    /// unless the message says otherwise (a CAM: digest between certificates).
    virtual SecurityProfile securityProfile() const { return SecurityProfile::Other; }
    /// Fields of the message's own the message trace shows on its lines (none by default).
    virtual std::vector<TraceField> traceFields() const { return {}; }

    /// Filled in by the medium when the message is sent.
    const std::string& sender() const { return sender_; }
    kernel::SimTime sentAt() const { return sentAt_; }
    /// The sender's count of messages before this one (0, 1, 2, …), over all its services.
    std::uint64_t sequence() const { return sequence_; }
    /// The whole 802.11 frame carrying it (MAC header to FCS: GeoNetworking, BTP, LLC/SNAP and the
    /// security envelope around byteSize(); FrameSize.h), as signed when it was sent.
    std::size_t frameBytes() const { return frameBytes_; }

    /// Its GeoNetworking header: a single-hop broadcast unless the message made itself a
    /// geo-broadcast; the sending station's router fills in the rest.
    const geonet::PacketHeader& geonet() const { return geonet_; }
    /// A copy of this message, for a station that forwards it (GeoNetworking); none (the
    /// default): the message is received, never forwarded.
    virtual std::unique_ptr<V2xMessage> clone() const { return nullptr; }

protected:
    /// Makes this message a geo-broadcast (GBC) to the stations in `area`.
    void geoBroadcastTo(const geonet::GeoArea& area) {
        geonet_.transport = geonet::Transport::GeoBroadcast;
        geonet_.area = area;
    }

private:
    friend class Medium;
    friend class geonet::Router;
    geonet::PacketHeader geonet_;
    std::string sender_;
    std::uint32_t senderIndex_ = 0;  // the medium's station index of sender_, stamped with it
    kernel::SimTime sentAt_;
    std::uint64_t sequence_ = 0;
    std::size_t frameBytes_ = 0;
};

}  // namespace sbsim::radio
