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
/// received them (the order a C++ service's indicate() sees them in). A reception appends one compact
/// row (two cache lines, no object: a station's receptions interleave with every other station's, so
/// one row per reception beats a column each); Python reads the numeric columns as read-only numpy
/// views, made in one pass on first access, and a message object only when one is asked for (at()).
class MessageBatch {
public:
    void add(const radio::V2xMessage& message, kernel::SimTime now);
    std::size_t size() const { return rows_.size(); }
    /// Message `i` as a record (made on demand).
    ReceivedMessage at(std::size_t i) const;
    const std::vector<std::string>& senders() const { return senders_; }
    std::vector<std::string> types() const;
    /// Makes room for `n` messages (the last batch's size: a station's batches are alike).
    void reserve(std::size_t n);

    struct Columns {
        std::vector<double> receivedAt, sentAt, sizes;
        std::vector<double> camPositions, camSpeeds, camHeadings;  ///< NaN for messages that are not CAMs
    };
    /// Made on first use; the batch is not added to once Python has it.
    const Columns& columns() const;

private:
    struct Row {
        double receivedAt, sentAt;
        std::uint64_t sequence;
        std::uint32_t size, frameBytes, type;  // type: into typeNames_
        std::uint8_t stationType;
        bool cam;
        // A CAM's x, y, speed, heading, acceleration, length, width, yaw rate, generation time.
        double camValues[9];
    };
    std::vector<Row> rows_;
    std::vector<std::string> typeNames_;
    std::vector<std::string> senders_;
    std::vector<std::pair<std::size_t, pybind11::object>> payloads_;  // Python services' messages only
    std::vector<std::pair<std::size_t, std::shared_ptr<facilities::DenmContent>>> denms_;
    mutable std::optional<Columns> columns_;
};

}  // namespace sbsim::services::python
