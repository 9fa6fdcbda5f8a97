#include "sbsim/services/python/MessageStore.h"

#include <typeinfo>

#include "sbsim/facilities/Cam.h"
#include "sbsim/services/python/PythonMessage.h"

namespace sbsim::services::python {

MessageStore::Place MessageStore::add(const radio::V2xMessage& message, kernel::SimTime now) {
    // A transmission is its sender's sequence number; the address only makes the test quick.
    if (&message == last_ && message.sequence() == lastSequence_ && now == lastTime_ && filling_ != nullptr &&
        filling_->senders.back() == message.sender()) {
        return {&current_, static_cast<std::uint32_t>(filling_->rows.size() - 1)};
    }
    if (filling_ == nullptr || filling_->rows.size() == kRows) {
        auto chunk = std::make_shared<Chunk>();
        chunk->rows.reserve(kRows);
        chunk->senders.reserve(kRows);
        filling_ = chunk.get();
        current_ = std::move(chunk);
    }
    last_ = &message;
    lastSequence_ = message.sequence();
    lastTime_ = now;
    const auto i = static_cast<std::uint32_t>(filling_->rows.size());
    const std::string_view type = message.typeName();
    std::uint32_t t = 0;
    while (t < typeNames_.size() && typeNames_[t] != type) ++t;
    if (t == typeNames_.size()) typeNames_.emplace_back(type);
    Row& row = filling_->rows.emplace_back();
    row.receivedAt = now.seconds();
    row.sentAt = message.sentAt().seconds();
    row.sequence = message.sequence();
    row.size = static_cast<std::uint32_t>(message.byteSize());
    row.frameBytes = static_cast<std::uint32_t>(message.frameBytes());
    row.type = t;
    row.cam = false;
    filling_->senders.push_back(message.sender());
    // The concrete types sbsim knows, by exact type (a failed dynamic_cast walks the hierarchy by name).
    const std::type_info& dynamic = typeid(message);
    if (dynamic == typeid(facilities::Cam)) {
        const facilities::CamContent& c = static_cast<const facilities::Cam&>(message).content();
        row.cam = true;
        row.stationType = static_cast<std::uint8_t>(c.stationType);
        row.camValues[0] = c.position.x();
        row.camValues[1] = c.position.y();
        row.camValues[2] = c.speed;
        row.camValues[3] = c.heading;
        row.camValues[4] = c.acceleration;
        row.camValues[5] = c.length;
        row.camValues[6] = c.width;
        row.camValues[7] = c.yawRate;
        row.camValues[8] = c.generationTime.seconds();
    } else if (dynamic == typeid(PythonMessage)) {
        filling_->payloads.emplace_back(i, static_cast<const PythonMessage&>(message).payload());
    } else if (dynamic == typeid(facilities::Denm)) {
        filling_->denms.emplace_back(
            i, std::make_shared<facilities::DenmContent>(static_cast<const facilities::Denm&>(message).content()));
    }
    return {&current_, i};
}

std::shared_ptr<MessageStore> MessageStore::shared() {
    // Not owned here: the store goes with the last service or batch that holds it (under the lock).
    static std::weak_ptr<MessageStore> store;
    std::shared_ptr<MessageStore> out = store.lock();
    if (!out) {
        out = std::make_shared<MessageStore>();
        store = out;
    }
    return out;
}

}  // namespace sbsim::services::python
