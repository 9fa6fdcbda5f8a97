#include "sbsim/radio/channel/Reception.h"

#include <algorithm>

#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Decibels.h"

namespace sbsim::radio {

namespace {
constexpr double kUnitsPerMw = 18446744073709551616.0;  // 2^64: scaling by it is exact
}  // namespace

Reception::Reception(const ChannelSettings& settings, Listener& listener)
    : listener_(listener),
      fer_(settings.ferTable),
      sensingMw_(dbToLinear(settings.sensingDbm)),
      noiseMw_(dbToLinear(settings.noiseDbm)),
      floorMw_(dbToLinear(settings.interferenceFloorDbm)),
      ratioDb_(linearToDb(settings.bandwidthHz / (settings.rateMbps * 1e6))) {}

double Reception::mwOf(Units units) { return static_cast<double>(units) / kUnitsPerMw; }

void Reception::addStation() {
    heard_.push_back(0);
    sensedBusy_.push_back(0);
    sending_.push_back(0);
    locked_.push_back(0);
    lockedLink_.push_back(nullptr);
    sendStart_.push_back(kernel::SimTime::fromNanoseconds(-1));
}

void Reception::startSending(Slot s, FrameId id, kernel::SimTime now) {
    locked_[s] = 0;
    sending_[s] = id;
    sendStart_[s] = now;
}

void Reception::frameStarts(FrameId id, const StepLinks& step, std::vector<Link>& drawn,
                            std::vector<std::uint32_t>* halfAtStart) {
    // Receivers one by one, in the step's order: carrier sense changes schedule events, so this
    // stays sequential.
    std::size_t j = 0;
    for (std::size_t k = 0; k < step.size(); ++k) {
        if (step.tier[k] == StepLinks::kDrawn) {
            linkStarts(id, drawn[j++]);
            continue;
        }
        // Interference only: below the sensing threshold, never detected, never decoded.
        const Slot r = step.receivers[k];
        if (halfAtStart != nullptr && sending_[r] != 0) halfAtStart->push_back(static_cast<std::uint32_t>(k));
        if (step.tier[k] == StepLinks::kBelowFloor) continue;
        setSensedPower(r, mwOf(hear(r, step.units[k])));
    }
}

Reception::Units Reception::hear(Slot r, Units units) {
    const Units total = heard_[r] + units;
    heard_[r] = total;
    if (locked_[r] != 0) {
        Link& decoding = *lockedLink_[r];
        decoding.maxInterferenceMw = std::max(decoding.maxInterferenceMw, mwOf(total - unitsOf(decoding.powerMw)));
    }
    return total;
}

void Reception::linkStarts(FrameId id, Link& link) {
    const Slot r = link.receiver;
    if (sending_[r] != 0) link.halfDuplex = true;
    if (link.powerMw < floorMw_) return;
    link.counted = true;
    const Units others = heard_[r];
    const bool decoding = locked_[r] != 0;
    const Units total = hear(r, unitsOf(link.powerMw));
    if (!decoding && sending_[r] == 0 && link.powerMw >= sensingMw_) {
        locked_[r] = id;
        lockedLink_[r] = &link;
        link.locked = true;
        link.maxInterferenceMw = mwOf(others);
    }
    setSensedPower(r, mwOf(total));
}

double Reception::frameEnds(FrameId id, kernel::SimTime start, Link& link) {
    const Slot r = link.receiver;
    if (locked_[r] == id) locked_[r] = 0;
    if (!link.counted) return 0;
    if (sentSince(r, start)) link.halfDuplex = true;
    return leave(r, unitsOf(link.powerMw));
}

void Reception::setSensedPower(Slot s, double mw) {
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
