#include "sbsim/radio/Medium.h"

#include <stdexcept>

#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Receiver.h"

namespace sbsim::radio {

namespace {
/// One frame's receptions at one time.
struct FrameDelivery : kernel::Message {
    static constexpr int kKind = 0x7632'7801;
    FrameDelivery(std::shared_ptr<const V2xMessage> m, std::vector<Receiver*> r, std::vector<std::string> s,
                  std::uint64_t changes)
        : kernel::Message("v2x frame", kKind),
          message(std::move(m)),
          receivers(std::move(r)),
          stations(std::move(s)),
          moduleChanges(changes) {}
    std::shared_ptr<const V2xMessage> message;
    std::vector<Receiver*> receivers;
    std::vector<std::string> stations;  // the receivers' names, should one leave meanwhile
    std::uint64_t moduleChanges;        // the simulation's when the receivers were taken
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
                          std::vector<std::string> stations, kernel::SimTime delay) {
    if (receivers.empty()) return;
    const std::uint64_t changes = simulation().moduleChanges();
    sendDirect(std::make_unique<FrameDelivery>(std::move(message), std::move(receivers), std::move(stations), changes),
               delay, *this);
}

void Medium::handleMessage(kernel::Message& msg) {
    if (msg.kind() != FrameDelivery::kKind) return kernel::Module::handleMessage(msg);
    const auto& frame = static_cast<const FrameDelivery&>(msg);
    Counts* counts = countsOf(*frame.message);  // one lookup per frame, not per reception
    const V2xMessage& message = *frame.message;
    const bool secured = certificates_.secured();
    const SecurityProfile profile = message.securityProfile();
    // The sender's index once per frame, each receiver's once per station (Receiver::mediumIndex_).
    const CertificatePolicy::Index sender = secured ? certificates_.index(message.sender()) : 0;
    if (simulation().moduleChanges() == frame.moduleChanges) {
        for (std::size_t k = 0; k < frame.receivers.size(); ++k) {
            if (counts != nullptr) ++counts->delivered;
            if (secured)
                certificates_.heard(certificateIndex(*frame.receivers[k], frame.stations[k]), sender, profile,
                                    simTime());
            frame.receivers[k]->receive(message);
        }
        return;
    }
    for (const std::string& station : frame.stations) {
        Receiver* receiver = receivingSide(station);
        if (receiver == nullptr) continue;  // it left
        if (counts != nullptr) ++counts->delivered;
        if (secured) certificates_.heard(certificateIndex(*receiver, station), sender, profile, simTime());
        receiver->receive(message);
    }
}

CertificatePolicy::Index Medium::certificateIndex(Receiver& receiver, const std::string& station) {
    if (!receiver.mediumIndex_) receiver.mediumIndex_ = certificates_.index(station);
    return *receiver.mediumIndex_;
}

void Medium::stamp(V2xMessage& message, const std::string& sender) {
    message.sender_ = sender;
    message.sentAt_ = simTime();
    message.sequence_ = sequences_[sender]++;
    const SecurityProfile profile = message.securityProfile();
    message.frameBytes_ = radio::frameBytes(message.byteSize(), message.gnTransport(), profile,
                                            certificates_.sign(sender, profile, simTime()));
    Counts& c = counts_[std::string(message.typeName())];
    ++(message.geonet().hops() > 1 ? c.forwarded : c.sent);
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
