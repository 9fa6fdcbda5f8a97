#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/facilities/Cam.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/V2xMessage.h"

namespace sbsim::services::python {

/// What a Python service is handed of one received message: a copy of its header and content, so
/// that Python may keep it past the call (the medium frees the message after its receptions).
struct ReceivedMessage {
    kernel::SimTime receivedAt;
    std::string type;
    std::string sender;
    kernel::SimTime sentAt;
    std::uint64_t sequence = 0;
    std::size_t size = 0;
    std::size_t frameBytes = 0;
    pybind11::object payload;  ///< a Python service's message's payload; None otherwise
    std::optional<facilities::CamContent> cam;
    std::optional<facilities::DenmContent> denm;

    static ReceivedMessage of(const radio::V2xMessage& message, kernel::SimTime now);
};

/// The messages one station received since its service's last batch, in the order the middleware
/// received them (the order a C++ service's indicate() sees them in). Its numeric columns are made
/// once, on first access, and handed out as read-only numpy views of the batch's own memory.
struct MessageBatch {
    std::vector<ReceivedMessage> messages;

    struct Columns {
        std::vector<double> receivedAt, sentAt, size;
        std::vector<double> camPosition, camSpeed, camHeading;  ///< NaN for messages that are not CAMs
    };
    /// Built on first use.
    const Columns& columns();

private:
    std::optional<Columns> columns_;
};

}  // namespace sbsim::services::python
