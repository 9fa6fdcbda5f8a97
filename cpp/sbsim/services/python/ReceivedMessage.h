#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

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
    pybind11::object payload;                       ///< a Python service's message's payload; None otherwise
    std::optional<facilities::CamContent> cam;      ///< without the low-frequency container
    std::shared_ptr<facilities::DenmContent> denm;  ///< rare: kept out of line

    static ReceivedMessage of(const radio::V2xMessage& message, kernel::SimTime now);
};

}  // namespace sbsim::services::python
