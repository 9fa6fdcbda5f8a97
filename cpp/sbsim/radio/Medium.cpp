#include "sbsim/radio/Medium.h"

#include <stdexcept>

#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Receiver.h"

namespace sbsim::radio {

namespace {
/// One frame's receptions at one time.
struct FrameDelivery : kernel::Message {
    static constexpr int kKind = 0x7632'7801;
    FrameDelivery(std::shared_ptr<const V2xMessage> m, std::vector<Receiver*> r, std::vector<Medium::StationIndex> s,
                  std::uint64_t changes)
        : kernel::Message("v2x frame", kKind),
          message(std::move(m)),
          receivers(std::move(r)),
          stations(std::move(s)),
          moduleChanges(changes) {}
    std::shared_ptr<const V2xMessage> message;
    std::vector<Receiver*> receivers;
    std::vector<Medium::StationIndex> stations;  // the receivers', to find them should one leave meanwhile
    std::uint64_t moduleChanges;                 // the simulation's when the receivers were taken
};
}  // namespace

Receiver* Medium::receivingSide(const std::string& stationId) const {
    kernel::Module* module = receiverOf(stationId);
    if (module == nullptr) return nullptr;
    // The station's module is asked for its receiving side, not switched on by type.
    auto* receiver = dynamic_cast<Receiver*>(module);
    if (receiver == nullptr) throw std::logic_error("station '" + stationId + "' cannot receive V2X messages");
    return receiver;
}

void Medium::deliverLater(std::shared_ptr<const V2xMessage> message, std::vector<Receiver*> receivers,
                          std::vector<StationIndex> stations, kernel::SimTime delay) {
    if (receivers.empty()) return;
    const std::uint64_t changes = simulation().moduleChanges();
    sendDirect(std::make_unique<FrameDelivery>(std::move(message), std::move(receivers), std::move(stations), changes),
               delay, *this);
}

void Medium::handleMessage(kernel::Message& msg) {
    if (msg.kind() != FrameDelivery::kKind) return kernel::Module::handleMessage(msg);
    auto& frame = static_cast<FrameDelivery&>(msg);
    const V2xMessage& message = *frame.message;
    if (simulation().moduleChanges() != frame.moduleChanges) {
        // Some station joined or left since the frame was sent: its receivers found again by name.
        std::size_t kept = 0;
        for (std::size_t k = 0; k < frame.stations.size(); ++k) {
            Receiver* receiver = receivingSide(certificates_.name(frame.stations[k]));
            if (receiver == nullptr) continue;  // it left
            frame.receivers[kept] = receiver;
            frame.stations[kept] = frame.stations[k];
            ++kept;
        }
        frame.receivers.resize(kept);
        frame.stations.resize(kept);
    }
    if (Counts* counts = countsOf(message)) counts->delivered += frame.receivers.size();
    // What each receiver heard is kept before any of them handles the message: the policy's
    // answers for one station do not depend on the others', and a station's own sending (a
    // forward while it receives) sees its reception recorded either way.
    if (certificates_.secured())
        certificates_.heardAll(frame.stations, message.senderIndex_, message.securityProfile(), simTime());
    for (Receiver* receiver : frame.receivers) receiver->receive(message);
}

void Medium::stamp(V2xMessage& message, const std::string& sender) {
    // The sender's name is looked up once per frame: its sequence and certificate go by index.
    const StationIndex index = stationIndex(sender);
    message.sender_ = sender;
    message.senderIndex_ = index;
    message.sentAt_ = simTime();
    if (sequences_.size() <= index) sequences_.resize(index + 1, 0);
    message.sequence_ = sequences_[index]++;
    const SecurityProfile profile = message.securityProfile();
    message.frameBytes_ = radio::frameBytes(message.byteSize(), message.gnTransport(), profile,
                                            certificates_.sign(index, profile, simTime()));
    auto c = counts_.find(message.typeName());
    if (c == counts_.end()) c = counts_.emplace(std::string(message.typeName()), Counts{}).first;
    ++(message.geonet().hops() > 1 ? c->second.forwarded : c->second.sent);
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
    c.countLink(static_cast<std::size_t>(distance / kDistanceBin), received);
}

}  // namespace sbsim::radio
