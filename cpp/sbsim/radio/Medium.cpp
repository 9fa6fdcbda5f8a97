#include "sbsim/radio/Medium.h"

namespace sbsim::radio {

void Medium::stamp(V2xMessage& message, const std::string& sender) {
    message.sender_ = sender;
    message.sentAt_ = simTime();
    ++counts_[std::string(message.typeName())].sent;
}

void Medium::delivered(const V2xMessage& message) {
    const auto it = counts_.find(message.typeName());
    if (it != counts_.end()) ++it->second.delivered;
}

}  // namespace sbsim::radio
