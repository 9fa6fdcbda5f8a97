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
    pybind11::object payload;                       ///< a Python service's message's payload; None otherwise
    std::optional<facilities::CamContent> cam;      ///< without the low-frequency container
    std::shared_ptr<facilities::DenmContent> denm;  ///< rare: kept out of line

    static ReceivedMessage of(const radio::V2xMessage& message, kernel::SimTime now);
};

/// The messages one station received since its service's last batch, in the order the middleware
/// received them (the order a C++ service's indicate() sees them in), kept as columns: a reception
/// appends a few numbers and its sender, no object. Python reads the numeric columns as read-only
/// numpy views of this memory; a message object is made only when one is asked for (at()).
class MessageBatch {
public:
    void add(const radio::V2xMessage& message, kernel::SimTime now);
    std::size_t size() const { return receivedAt_.size(); }
    /// Message `i` as a record (made on demand).
    ReceivedMessage at(std::size_t i) const;
    const std::vector<double>& receivedAt() const { return receivedAt_; }
    const std::vector<double>& sentAt() const { return sentAt_; }
    const std::vector<double>& sizes() const { return sizes_; }
    const std::vector<double>& camPositions() const { return camPosition_; }  ///< x, y per message
    const std::vector<double>& camSpeeds() const { return camSpeed_; }
    const std::vector<double>& camHeadings() const { return camHeading_; }
    const std::vector<std::string>& senders() const { return senders_; }
    std::vector<std::string> types() const;
    /// Makes room for `n` messages (the last batch's size: a station's batches are alike).
    void reserve(std::size_t n);

private:
    std::vector<double> receivedAt_, sentAt_, sizes_;
    std::vector<std::uint64_t> sequences_, frameBytes_;
    std::vector<std::uint32_t> types_;  // into typeNames_
    std::vector<std::string> typeNames_;
    std::vector<std::string> senders_;
    // NaN for messages that are not CAMs (NaN x: none).
    std::vector<double> camPosition_, camSpeed_, camHeading_, camRest_;  // rest: acceleration, length, width,
                                                                         // yaw rate, generation time, station type
    std::vector<std::pair<std::size_t, pybind11::object>> payloads_;     // Python services' messages only
    std::vector<std::pair<std::size_t, std::shared_ptr<facilities::DenmContent>>> denms_;
};

}  // namespace sbsim::services::python
