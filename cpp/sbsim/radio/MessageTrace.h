#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/V2xMessage.h"

namespace sbsim::radio {

/// Why a station did not receive a message (the `reason` of a trace's lost line).
enum class LossReason {
    Sensing,      ///< received below the sensing threshold
    Propagation,  ///< detected, but lost to noise alone (FER at its SNR)
    Collision,    ///< lost to interference: overlapping frames, or the receiver was busy with another
    HalfDuplex,   ///< the receiver was transmitting during the frame
    Queue,        ///< dropped at the sender: its queue was full
    Range,        ///< disc model: beyond the range
    Fade,         ///< disc model: the linear fade dropped it
};
SBSIM_API std::string_view lossReasonName(LossReason reason);

/// One line of the message trace (--messages). Which optional fields are set depends on the event.
struct TraceLine {
    enum class Event { Tx, Rx, Lost };
    Event event = Event::Tx;
    kernel::SimTime t;
    const V2xMessage* message = nullptr;
    std::string_view station;
    std::string_view sender;  ///< rx and lost
    std::uint64_t seq = 0;
    double x = 0, y = 0;                          ///< tx
    std::optional<double> cbr;                    ///< tx
    double distance = 0;                          ///< rx and lost
    double delay = 0;                             ///< rx, s
    std::optional<double> powerDbm, sinrDb;       ///< rx, channel model only
    LossReason reason = LossReason::Propagation;  ///< lost
};

/// A station's DCC state changed (the channel model's congestion control, every 100 ms sample).
struct DccChange {
    kernel::SimTime t;
    std::string_view station;
    std::string_view state;    ///< DccStateMachine::name()
    double cbr = 0;            ///< the sample that changed it
    kernel::SimTime interval;  ///< the least time between two transmissions the new state allows
};

/// Where a medium reports what happened to each message. Lines may come with a time later than
/// `now` (a disc-model reception after its latency); a trace writes them in time order.
class SBSIM_API MessageTrace {
public:
    virtual ~MessageTrace() = default;
    virtual void record(const TraceLine& line, kernel::SimTime now) = 0;
    /// A station's DCC state changed at `change.t` = now (media without DCC never call it).
    virtual void dccChanged(const DccChange& /*change*/) {}
};

}  // namespace sbsim::radio
