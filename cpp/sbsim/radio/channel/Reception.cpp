#include "sbsim/radio/channel/Reception.h"

#include <algorithm>

#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Decibels.h"

namespace sbsim::radio {

Reception::Reception(const ChannelSettings& settings, Listener& listener)
    : listener_(listener),
      fer_(settings.ferTable),
      sensingMw_(dbToLinear(settings.sensingDbm)),
      noiseMw_(dbToLinear(settings.noiseDbm)),
      floorMw_(dbToLinear(settings.interferenceFloorDbm)),
      ratioDb_(linearToDb(settings.bandwidthHz / (settings.rateMbps * 1e6))) {}

void Reception::addStation() {
    sensedMw_.push_back(0);
    sensedBusy_.push_back(0);
    sending_.push_back(0);
    locked_.push_back(0);
    incoming_.emplace_back();
}

void Reception::startSending(Slot s, FrameId id) {
    for (const Incoming& in : incoming_[s]) (*in.links)[in.link].halfDuplex = true;
    locked_[s] = 0;
    sending_[s] = id;
}

void Reception::frameStarts(FrameId id, std::vector<Link>& links) {
    // Receivers one by one, in slot order: carrier sense changes schedule events, so this stays
    // sequential.
    for (std::uint32_t k = 0; k < links.size(); ++k) {
        Link& link = links[k];
        const Slot r = link.receiver;
        if (sending_[r] != 0) link.halfDuplex = true;
        if (link.powerMw < floorMw_) continue;
        link.counted = true;
        std::vector<Incoming>& in = incoming_[r];
        double others = 0;
        for (const Incoming& e : in) others += e.mw;
        link.maxInterferenceMw = others;
        const double total = others + link.powerMw;
        for (const Incoming& e : in) {
            Link& old = (*e.links)[e.link];
            old.maxInterferenceMw = std::max(old.maxInterferenceMw, std::max(0.0, total - e.mw));
        }
        if (sending_[r] == 0 && locked_[r] == 0 && link.powerMw >= sensingMw_) {
            locked_[r] = id;
            link.locked = true;
        }
        in.push_back({&links, k, link.powerMw});
        setSensedPower(r, total);
    }
}

double Reception::powerWithout(Slot r, const std::vector<Link>& links) {
    std::vector<Incoming>& in = incoming_[r];
    in.erase(std::remove_if(in.begin(), in.end(), [&](const Incoming& e) { return e.links == &links; }), in.end());
    double total = 0;
    for (const Incoming& e : in) total += e.mw;
    return total;
}

void Reception::setSensedPower(Slot s, double mw) {
    sensedMw_[s] = mw;
    const bool busy = mw >= sensingMw_;
    if (busy == static_cast<bool>(sensedBusy_[s])) return;
    sensedBusy_[s] = busy;
    listener_.channelSensed(s, busy);
}

std::optional<LossReason> Reception::decode(const Link& link, std::uint64_t frameKey, std::uint64_t receiverKey,
                                            double& sinrDb) const {
    if (link.halfDuplex) return LossReason::HalfDuplex;
    if (link.powerMw < sensingMw_) return LossReason::Sensing;
    if (!link.locked) return LossReason::Collision;  // the receiver was decoding another frame
    sinrDb = linearToDb(link.powerMw / (noiseMw_ + link.maxInterferenceMw));
    const double snrDb = linearToDb(link.powerMw / noiseMw_);
    const double ferWith = fer_.ferAtEbN0Db(sinrDb + ratioDb_);
    const double ferWithout = fer_.ferAtEbN0Db(snrDb + ratioDb_);
    auto random = CounterRandom::ofFrame(frameKey, receiverKey, DrawPurpose::Decode);
    const double u = random.uniform01();
    if (u < ferWithout) return LossReason::Propagation;
    if (u < ferWith) return LossReason::Collision;
    return std::nullopt;
}

}  // namespace sbsim::radio
