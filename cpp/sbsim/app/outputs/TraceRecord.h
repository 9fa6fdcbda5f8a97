#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/app/outputs/MessageTraceFilter.h"
#include "sbsim/facilities/DenmPhase.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/MessageTrace.h"
#include "sbsim/radio/TraceField.h"

namespace sbsim::app {

/// One line of the message trace as its writer gets it: a radio line (tx, rx, lost) or a DENM
/// phase line (denm), owning what it shows, since it may wait for its time after the message is
/// gone (a disc-model reception after its latency). Which fields are set depends on the event,
/// as in radio::TraceLine; a denm line has station, phase, action and cause.
struct TraceRecord {
    using Event = MessageTraceFilter::Event;
    Event event = Event::Tx;
    kernel::SimTime t;
    std::string type;  ///< empty for denm
    std::string station;
    std::string sender;  ///< rx and lost
    std::uint64_t seq = 0;
    std::uint64_t bytes = 0;                                    ///< tx: the message's own
    std::uint64_t frameBytes = 0;                               ///< tx: the whole 802.11 frame
    double x = 0, y = 0;                                        ///< tx
    std::optional<double> cbr;                                  ///< tx
    double distance = 0;                                        ///< rx and lost
    double delay = 0;                                           ///< rx, s
    std::optional<double> powerDbm, sinrDb;                     ///< rx, channel model only
    radio::LossReason reason = radio::LossReason::Propagation;  ///< lost
    std::string_view phase;                                     ///< denm (a static name)
    std::string_view dccState;                                  ///< dcc (a static name)
    double dccInterval = 0;                                     ///< dcc, s
    std::string action;                                         ///< denm
    std::int64_t cause = 0;                                     ///< denm
    std::vector<radio::TraceField> fields;                      ///< the message's own (radio lines)
    /// A geo-broadcast's GeoNetworking: its source, the transmissions so far including this frame's,
    /// and the station a greedy forward addressed (radio lines of a GBC message only).
    bool geoBroadcast = false;
    std::string source, nextHop;
    std::uint64_t hops = 0;

    static Event eventOf(radio::TraceLine::Event e) {
        return e == radio::TraceLine::Event::Tx   ? Event::Tx
               : e == radio::TraceLine::Event::Rx ? Event::Rx
                                                  : Event::Lost;
    }
    static TraceRecord of(const radio::TraceLine& line) {
        TraceRecord r;
        r.event = eventOf(line.event);
        r.t = line.t;
        r.type = line.message->typeName();
        r.station = line.station;
        r.sender = line.sender;
        r.seq = line.seq;
        r.bytes = line.message->byteSize();
        r.frameBytes = line.message->frameBytes();
        r.x = line.x;
        r.y = line.y;
        r.cbr = line.cbr;
        r.distance = line.distance;
        r.delay = line.delay;
        r.powerDbm = line.powerDbm;
        r.sinrDb = line.sinrDb;
        r.reason = line.reason;
        r.fields = line.message->traceFields();
        if (const auto& gn = line.message->geonet(); gn.geoBroadcast()) {
            r.geoBroadcast = true;
            r.source = gn.source;
            r.hops = gn.hops();
            r.nextHop = gn.nextHop;
        }
        return r;
    }
    static TraceRecord of(const radio::DccChange& c) {
        TraceRecord r;
        r.event = Event::Dcc;
        r.t = c.t;
        r.station = c.station;
        r.dccState = c.state;
        r.cbr = c.cbr;
        r.dccInterval = c.interval.seconds();
        return r;
    }
    static TraceRecord of(const facilities::DenmPhaseEvent& e) {
        TraceRecord r;
        r.event = Event::Denm;
        r.t = e.time;
        r.station = e.station;
        r.phase = facilities::phaseName(e.phase);
        r.action = e.action.str();
        r.cause = e.cause;
        return r;
    }
};

}  // namespace sbsim::app
