#include "sbsim/radio/Medium.h"

#include <stdexcept>

#include "sbsim/radio/Receiver.h"

namespace sbsim::radio {

namespace {
/// One frame's receptions at one time. Receivers are named, not pointed at: a station may leave
/// (its middleware removed) between the transmission and the delivery.
struct FrameDelivery : kernel::Message {
    static constexpr int kKind = 0x7632'7801;
    FrameDelivery(std::shared_ptr<const V2xMessage> m, std::vector<std::string> s)
        : kernel::Message("v2x frame", kKind), message(std::move(m)), stations(std::move(s)) {}
    std::shared_ptr<const V2xMessage> message;
    std::vector<std::string> stations;
};
}  // namespace

void Medium::deliverLater(std::shared_ptr<const V2xMessage> message, std::vector<std::string> stations,
                          kernel::SimTime delay) {
    if (stations.empty()) return;
    sendDirect(std::make_unique<FrameDelivery>(std::move(message), std::move(stations)), delay, *this);
}

void Medium::handleMessage(kernel::Message& msg) {
    if (msg.kind() != FrameDelivery::kKind) return kernel::Module::handleMessage(msg);
    const auto& frame = static_cast<const FrameDelivery&>(msg);
    for (const std::string& station : frame.stations) {
        kernel::Module* module = receiverOf(station);
        if (module == nullptr) continue;  // left since the transmission
        // The station's module is asked for its receiving side, not switched on by type.
        auto* receiver = dynamic_cast<Receiver*>(module);
        if (receiver == nullptr) throw std::logic_error("station '" + station + "' cannot receive V2X messages");
        receiver->receive(*frame.message);
    }
}

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
