#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sbsim/services/python/MessageStore.h"
#include "sbsim/services/python/ReceivedMessage.h"

namespace sbsim::services::python {

/// The messages one station received since its service's last batch, in the order the middleware
/// received them (the order a C++ service's indicate() sees them in). A reception appends a 4-byte
/// reference to the message's row in the run's MessageStore (written once per frame, whatever the
/// number of receivers), so the stations' interleaved receptions touch little memory; Python reads
/// the numeric columns as read-only numpy views, gathered in one pass on first access, and a message
/// object only when one is asked for (at()). The service reuses a batch Python did not keep.
class MessageBatch {
public:
    explicit MessageBatch(std::shared_ptr<MessageStore> store) : store_(std::move(store)) {}

    void add(const radio::V2xMessage& message, kernel::SimTime now) {
        const MessageStore::Place place = store_->add(message, now);
        if (place.chunk->get() != lastChunk_) {
            chunks_.push_back(*place.chunk);
            lastChunk_ = place.chunk->get();
        }
        refs_.push_back(static_cast<std::uint32_t>(chunks_.size() - 1) << MessageStore::kRowBits | place.row);
    }
    std::size_t size() const { return refs_.size(); }
    /// Empties the batch for the next interval, keeping its memory.
    void clear();
    /// Message `i` as a record (made on demand).
    ReceivedMessage at(std::size_t i) const;
    std::vector<std::string> senders() const;
    std::vector<std::string> types() const;

    /// The numeric columns Python reads (NaN where a message is not a CAM, for the CAM's).
    enum class Column : std::uint8_t { ReceivedAt, SentAt, Size, CamPosition, CamSpeed, CamHeading, kCount };
    /// Gathered on first read (only the columns a service reads); the batch is not added to once
    /// Python has it. CamPosition holds x, y per message.
    const std::vector<double>& column(Column which) const;

private:
    const MessageStore::Chunk& chunk(std::size_t i) const { return *chunks_[refs_[i] >> MessageStore::kRowBits]; }
    std::uint32_t rowIndex(std::size_t i) const { return refs_[i] & (MessageStore::kRows - 1); }
    const MessageStore::Row& row(std::size_t i) const { return chunk(i).rows[rowIndex(i)]; }

    std::shared_ptr<MessageStore> store_;
    std::vector<std::uint32_t> refs_;  // (slot in chunks_, row)
    std::vector<std::shared_ptr<const MessageStore::Chunk>> chunks_;
    const MessageStore::Chunk* lastChunk_ = nullptr;  // chunks_.back(), kept here: one cache line less per reception
    mutable std::array<std::vector<double>, static_cast<std::size_t>(Column::kCount)> columns_;
    mutable std::uint32_t made_ = 0;  // a bit per column gathered
};

}  // namespace sbsim::services::python
