#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/facilities/Denm.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/V2xMessage.h"

namespace sbsim::services::python {

/// The messages Python services received, one row per message received at one time, not per
/// reception: a frame reaches hundreds of stations at once, and each Python service's batch keeps
/// only a 4-byte reference to the row (MessageBatch). The rows live in chunks that the batches
/// referring to them keep alive; the store itself keeps only the chunk it fills. Shared by every
/// Python service of the run (shared()); used on the simulation's thread only, which holds the
/// interpreter's lock (the payloads are Python objects).
class MessageStore {
public:
    /// Rows per chunk: a reference is (the batch's chunk slot, the row), packed in 32 bits.
    static constexpr unsigned kRowBits = 12;
    static constexpr std::uint32_t kRows = 1U << kRowBits;

    struct Row {
        double receivedAt, sentAt;
        std::uint64_t sequence;
        std::uint32_t size, frameBytes, type;  // type: into typeNames()
        std::uint8_t stationType;
        bool cam;
        // A CAM's x, y, speed, heading, acceleration, length, width, yaw rate, generation time.
        double camValues[9];
    };
    struct Chunk {
        std::vector<Row> rows;
        std::vector<std::string> senders;
        std::vector<std::pair<std::uint32_t, pybind11::object>> payloads;  // Python services' messages only
        std::vector<std::pair<std::uint32_t, std::shared_ptr<facilities::DenmContent>>> denms;
    };
    /// Where a message's row is.
    struct Place {
        const std::shared_ptr<const Chunk>* chunk;  // the store's current chunk; copy it to keep it
        std::uint32_t row;
    };

    /// The row of `message` received at `now`: the last one's when it is the same transmission (its
    /// sender, sequence and time), else a new row.
    Place add(const radio::V2xMessage& message, kernel::SimTime now);
    const std::vector<std::string>& typeNames() const { return typeNames_; }

    /// The run's store: made by the first Python service, freed with the last holder.
    static std::shared_ptr<MessageStore> shared();

private:
    std::shared_ptr<const Chunk> current_;
    Chunk* filling_ = nullptr;  // current_, writable here only
    std::vector<std::string> typeNames_;
    const radio::V2xMessage* last_ = nullptr;
    std::uint64_t lastSequence_ = 0;
    kernel::SimTime lastTime_;
};

}  // namespace sbsim::services::python
