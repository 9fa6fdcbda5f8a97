#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>

#include "sbsim/facilities/ActionId.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Message.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/services/den/Repetition.h"

namespace sbsim::services {

class Service;

/// The originating side of the DEN basic service (EN 302 637-3) for one station's service: action
/// ids, sending a DENM as geo-broadcast through the station's GeoNetworking router, its repetition,
/// and the cancellation that ends an event. DenService, RsuDenService and Python services send
/// their DENMs through one, so their DENMs are the same messages with the same trace lines and
/// DENM phase reports.
///
/// The repetition timers are the owner's events: its handleMessage() passes them to handle().
class SBSIM_API DenmSender {
public:
    explicit DenmSender(Service& owner) : owner_(owner) {}
    /// Cancels the pending repetitions (the owner's kernel module is still there: a member goes first).
    ~DenmSender();
    DenmSender(const DenmSender&) = delete;
    DenmSender& operator=(const DenmSender&) = delete;

    /// The next action id of the station (sequence numbers from 1).
    facilities::ActionId requestActionId();
    /// Sends `denm` now and, with `repetition`, again every interval (the same content) until the
    /// duration passed or the event is terminated. An action sent before is an update.
    void send(const facilities::DenmContent& denm, std::optional<Repetition> repetition = std::nullopt);
    /// Ends the station's event `action`: no more repetitions, one cancellation DENM (reference
    /// time now) to the same area. False, sending nothing, if the event is not the station's or
    /// already ended.
    bool terminate(const facilities::ActionId& action);
    /// Whether `action` is one of the station's events still being repeated.
    bool repeating(const facilities::ActionId& action) const { return active_.count(action) != 0; }
    /// Whether `action` is one of the station's events not terminated.
    bool live(const facilities::ActionId& action) const { return sentEvents_.count(action) != 0; }
    /// Takes `msg` if it is one of this sender's repetition timers (sending the repetition).
    bool handle(kernel::Message& msg);
    std::size_t sent() const { return sent_; }

private:
    struct Active {
        facilities::DenmContent denm;
        Repetition repetition;
        kernel::SimTime first;
        std::unique_ptr<kernel::Message> timer;
    };
    void transmit(const facilities::DenmContent& denm);

    Service& owner_;
    std::map<facilities::ActionId, Active> active_;
    std::uint32_t sequence_ = 0;
    std::size_t sent_ = 0;
    std::map<facilities::ActionId, facilities::DenmContent> sentEvents_;  // the last version of each live event
};

}  // namespace sbsim::services
