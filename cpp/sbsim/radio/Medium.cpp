#include "sbsim/radio/Medium.h"

namespace sbsim::radio {

void Medium::stamp(V2xMessage& message, const std::string& sender) {
    message.sender_ = sender;
    message.sentAt_ = simTime();
    message.sequence_ = sequences_[sender]++;
    ++counts_[std::string(message.typeName())].sent;
}

Medium::Counts* Medium::countsOf(const V2xMessage& message) {
    const auto it = counts_.find(message.typeName());
    return it == counts_.end() ? nullptr : &it->second;
}

void Medium::countLink(const V2xMessage& message, double distance, bool received) {
    if (Counts* c = countsOf(message)) countLink(*c, distance, received);
}

void Medium::countLink(Counts& c, double distance, bool received) {
    if (!(distance >= 0)) return;
    const auto bin = static_cast<std::size_t>(distance / kDistanceBin);
    if (c.linkStations.size() <= bin) {
        c.linkStations.resize(bin + 1);
        c.linkReceptions.resize(bin + 1);
    }
    ++c.linkStations[bin];
    if (received) ++c.linkReceptions[bin];
}

void Medium::delivered(const V2xMessage& message) {
    const auto it = counts_.find(message.typeName());
    if (it != counts_.end()) ++it->second.delivered;
}

}  // namespace sbsim::radio
