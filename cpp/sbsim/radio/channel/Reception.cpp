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

Reception::Units Reception::unitsOf(double mw) {
    // Whole milliwatts and the fraction apart, each exact in 64 bits (a link's power is far below
    // 2^64 mW): the same value as a direct conversion, without libgcc's out-of-line one per link.
    const auto whole = static_cast<std::uint64_t>(mw);
    const auto fraction = static_cast<std::uint64_t>((mw - static_cast<double>(whole)) * kUnitsPerMw);
    return (static_cast<Units>(whole) << 64) + fraction;
}

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

void Reception::frameStarts(FrameId id, std::vector<Link>& links) {
    // Receivers one by one, in slot order: carrier sense changes schedule events, so this stays
    // sequential.
    for (Link& link : links) {
        const Slot r = link.receiver;
        if (sending_[r] != 0) link.halfDuplex = true;
        if (link.powerMw < floorMw_) continue;
        link.counted = true;
        const Units others = heard_[r];
        const Units total = others + unitsOf(link.powerMw);
        heard_[r] = total;
        if (locked_[r] != 0) {
            Link& decoding = *lockedLink_[r];
            decoding.maxInterferenceMw = std::max(decoding.maxInterferenceMw, mwOf(total - unitsOf(decoding.powerMw)));
        } else if (sending_[r] == 0 && link.powerMw >= sensingMw_) {
            locked_[r] = id;
            lockedLink_[r] = &link;
            link.locked = true;
            link.maxInterferenceMw = mwOf(others);
        }
        setSensedPower(r, mwOf(total));
    }
}

double Reception::frameEnds(FrameId id, kernel::SimTime start, Link& link) {
    const Slot r = link.receiver;
    if (locked_[r] == id) locked_[r] = 0;
    if (!link.counted) return 0;
    if (sendStart_[r] >= start) link.halfDuplex = true;
    heard_[r] -= unitsOf(link.powerMw);
    return mwOf(heard_[r]);
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
