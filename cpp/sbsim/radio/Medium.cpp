#include "sbsim/radio/Medium.h"

#include <cassert>
#include <stdexcept>

#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Receiver.h"

namespace sbsim::radio {

struct Medium::FrameDelivery : kernel::Message {
    static constexpr int kKind = 0x7632'7801;
    FrameDelivery() : kernel::Message("v2x frame", kKind) {}
    std::shared_ptr<const V2xMessage> message;
    std::shared_ptr<const Medium::Recipients> recipients;  // its stations, to find them should one leave meanwhile
    bool keptByMedium = false;          // the list may come again, unchanged, for the sender's next frames
    std::uint64_t receiverChanges = 0;  // the medium's receiverChanges() when the receivers were taken
};

Medium::Medium(Directory directory) : kernel::Module("medium"), directory_(std::move(directory)) {}

// The frames on the air leave the event set as they go (a scheduled message removes itself).
Medium::~Medium() = default;

Receiver* Medium::receivingSide(const std::string& stationId) {
    kernel::Module* module = receiverOf(stationId);
    if (module == nullptr) return nullptr;
    // The station's module is asked for its receiving side, not switched on by type.
    auto* receiver = dynamic_cast<Receiver*>(module);
    if (receiver == nullptr) throw std::logic_error("station '" + stationId + "' cannot receive V2X messages");
    if (everyReceiverRegistered_) {
        // A receiver that never said what it takes takes everything: frames are then walked.
        const std::optional<StationIndex> index = certificates_.find(stationId);
        if (!index || !interest_.registered(*index)) everyReceiverRegistered_ = false;
    }
    return receiver;
}

Receiver* Medium::receivingSide(StationIndex station, const std::string& stationId) {
    if (receiversFilledAt_ != receiverChanges()) {
        receiverKnownAt_.assign(receiverKnownAt_.size(), 0);
        receiversFilledAt_ = receiverChanges();
    }
    if (station < receiverKnownAt_.size() && receiverKnownAt_[station]) return receiverAt_[station];
    Receiver* receiver = receivingSide(stationId);
    if (receiverKnownAt_.size() <= station) {
        receiverKnownAt_.resize(station + 1, 0);
        receiverAt_.resize(station + 1, nullptr);
    }
    receiverAt_[station] = receiver;
    receiverKnownAt_[station] = 1;
    return receiver;
}

std::uint64_t Medium::receiverChanges() const {
    // Either count only grows; the reported one starts above any module count it replaces.
    return reportsStationChanges_ ? stationChanges_ : simulation().moduleChanges();
}

void Medium::reportStationChanges() {
    if (reportsStationChanges_) return;
    reportsStationChanges_ = true;
    // A fresh count, distinct from every value receiverChanges() had: all kept receivers are dropped.
    stationChanges_ = simulation().moduleChanges() + 1;
}

void Medium::stationChanged(const std::string& stationId) {
    const bool kept = reportsStationChanges_ && receiversFilledAt_ == stationChanges_;
    ++stationChanges_;
    if (!kept) return;  // nothing kept is still trusted: all are looked up again anyway
    // Only this station is looked up again; the others' kept answers stay as the count moves on.
    const std::optional<StationIndex> index = certificates_.find(stationId);
    if (index && *index < receiverKnownAt_.size()) receiverKnownAt_[*index] = 0;
    receiversFilledAt_ = stationChanges_;
}

void Medium::deliverLater(std::shared_ptr<const V2xMessage> message, Receivers receivers,
                          std::vector<StationIndex> stations, kernel::SimTime delay) {
    if (receivers.empty()) return;
    queue(std::move(message), std::make_shared<const Recipients>(Recipients{std::move(receivers), std::move(stations)}),
          false, delay);
}

void Medium::deliverLater(std::shared_ptr<const V2xMessage> message, std::shared_ptr<const Recipients> recipients,
                          kernel::SimTime delay) {
    queue(std::move(message), std::move(recipients), true, delay);
}

void Medium::queue(std::shared_ptr<const V2xMessage> message, std::shared_ptr<const Recipients> recipients,
                   bool keptByMedium, kernel::SimTime delay) {
    if (recipients == nullptr || recipients->receivers.empty()) return;
    if (delay < kernel::SimTime::zero()) throw std::invalid_argument("negative delay for a V2X frame");
    if (spareFrames_.empty()) {
        frames_.push_back(std::make_unique<FrameDelivery>());
        spareFrames_.push_back(frames_.back().get());
    }
    FrameDelivery& frame = *spareFrames_.back();
    spareFrames_.pop_back();
    frame.message = std::move(message);
    frame.recipients = std::move(recipients);
    frame.keptByMedium = keptByMedium;
    frame.receiverChanges = receiverChanges();
    // Scheduled as sendDirect() would hand it over: the same time and place among the events.
    scheduleAt(simTime() + delay, frame);
}

void Medium::handleMessage(kernel::Message& msg) {
    if (msg.kind() != FrameDelivery::kKind) return kernel::Module::handleMessage(msg);
    auto& frame = static_cast<FrameDelivery&>(msg);
    // Spare again once handled, however that ends; what it held is let go of then.
    struct Spare {
        Medium& medium;
        FrameDelivery& frame;
        ~Spare() {
            frame.recipients.reset();  // in the order a freed event let go of them
            frame.message.reset();
            medium.spareFrames_.push_back(&frame);
        }
    } spare{*this, frame};
    const V2xMessage& message = *frame.message;
    const Recipients* recipients = frame.recipients.get();
    Recipients found;
    if (receiverChanges() != frame.receiverChanges) {
        // Some station joined or left since the frame was sent: its receivers found again.
        for (const StationIndex station : recipients->stations) {
            Receiver* receiver = receivingSide(station, certificates_.name(station));
            if (receiver == nullptr) continue;  // it left
            found.receivers.push_back(receiver);
            found.stations.push_back(station);
        }
        recipients = &found;
    }
    if (Counts* counts = countsOf(message)) counts->delivered += recipients->receivers.size();
    // What each receiver heard is kept before any of them handles the message: the policy's
    // answers for one station do not depend on the others', and a station's own sending (a
    // forward while it receives) sees its reception recorded either way.
    if (certificates_.secured()) {
        if (recipients == frame.recipients.get() && frame.keptByMedium) {
            // The sender's list of the step, held by the policy so its next frames cost no walk.
            certificates_.heardAll(LastHeard::List(frame.recipients, &frame.recipients->stations), message.senderIndex_,
                                   message.securityProfile(), simTime());
        } else {
            certificates_.heardAll(recipients->stations, message.senderIndex_, message.securityProfile(), simTime());
        }
    }
    if (toEveryReceiver(message)) {
        for (Receiver* receiver : recipients->receivers) receiver->receive(message);
        return;
    }
    // Only the stations that take the type are visited: a bit test each, in the order found;
    // none when no station takes it (every receiver registered its types).
    const ReceptionInterest::Takers takers = interest_.takersOf(message.typeName());
    if (everyReceiverRegistered_ && takers.noRegisteredTaker()) return;
    const std::size_t n = recipients->receivers.size();
    for (std::size_t k = 0; k < n; ++k) {
        if (takers.takes(recipients->stations[k])) recipients->receivers[k]->receive(message);
    }
}

bool Medium::toEveryReceiver(const V2xMessage& message) {
    if (!interest_.anyRestricted() || !layersTake_ || message.geonet().geoBroadcast()) return true;
    const std::type_info* type = &typeid(message);
    for (const auto& [known, taken] : layersTakeKnown_) {
        if (known == type) return taken;
    }
    const bool taken = layersTake_(message);
    layersTakeKnown_.emplace_back(type, taken);
    return taken;
}

void Medium::broadcastFrom(StationIndex index, const std::string& sender, std::unique_ptr<V2xMessage> message) {
    assert(certificates_.name(index) == sender);
    knownSender_ = &sender;
    knownSenderIndex_ = index;
    // Forgotten however broadcast() ends (it may throw before its stamp).
    struct Forget {
        const std::string*& known;
        ~Forget() { known = nullptr; }
    } forget{knownSender_};
    broadcast(sender, std::move(message));
}

void Medium::stamp(V2xMessage& message, const std::string& sender) {
    // The sender's name is looked up at most once per frame (not at all when broadcastFrom() named
    // its index): its sequence and certificate go by index.
    const StationIndex index = &sender == knownSender_ ? knownSenderIndex_ : stationIndex(sender);
    knownSender_ = nullptr;
    message.sender_ = sender;
    message.senderIndex_ = index;
    message.sentAt_ = simTime();
    if (sequences_.size() <= index) sequences_.resize(index + 1, 0);
    message.sequence_ = sequences_[index]++;
    const SecurityProfile profile = message.securityProfile();
    message.frameBytes_ = radio::frameBytes(message.byteSize(), message.gnTransport(), profile,
                                            certificates_.sign(index, profile, simTime()));
    Counts* c = countsOf(message);
    if (c == nullptr) c = &counts_.emplace(std::string(message.typeName()), Counts{}).first->second;
    ++(message.geonet().hops() > 1 ? c->forwarded : c->sent);
}

Medium::Counts* Medium::countsOf(const V2xMessage& message) {
    // Asked three times per frame (stamp, the medium's links, the delivery), nearly always for the
    // type asked last: its name compared once instead of a search of the map.
    const std::string_view type = message.typeName();
    if (lastCounts_ != nullptr && type == lastCountsType_) return lastCounts_;
    const auto it = counts_.find(type);
    if (it == counts_.end()) return nullptr;
    lastCountsType_ = it->first;  // the map's own key: nodes are never erased
    lastCounts_ = &it->second;
    return lastCounts_;
}

void Medium::countLink(const V2xMessage& message, double distance, bool received) {
    if (Counts* c = countsOf(message)) countLink(*c, distance, received);
}

void Medium::countLink(Counts& c, double distance, bool received) {
    if (!(distance >= 0)) return;
    c.countLink(static_cast<std::size_t>(distance / kDistanceBin), received);
}

}  // namespace sbsim::radio
