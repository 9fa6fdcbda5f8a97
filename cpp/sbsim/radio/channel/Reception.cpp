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
      ratioDb_(linearToDb(settings.bandwidthHz / (settings.rateMbps * 1e6))),
      sensingUnits_(unitsOf(sensingMw_)) {}

void Reception::addStation() {
    heard_.push_back(0);
    sensedBusy_.push_back(0);
    sending_.push_back(0);
    locked_.push_back(0);
    lockedLink_.push_back(nullptr);
    sendStart_.push_back(kernel::SimTime::fromNanoseconds(-1));
    lockCell_.push_back(-1);
    lockOwn_.push_back(0);
    segmentNearMw_.push_back(0);
    lockedMaxMw_.push_back(0);
    cell_.push_back(-1);
    segmentFrom_.push_back(0);
}

void Reception::growField(std::int32_t cell) {
    const auto n = static_cast<std::size_t>(cell) + 1;
    if (field_.size() >= n) return;
    field_.resize(n, 0);
    logged_.resize(n, 0);
    log_.resize(n * kLog, 0);
}

void Reception::farStarts(const StepLinks& step) {
    for (std::size_t k = 0; k < step.farCell.size(); ++k) {
        const Units units = step.farUnits[k];
        if (units == 0) continue;
        const std::int32_t c = step.farCell[k];
        growField(c);
        const Units total = field_[c] + units;
        field_[c] = total;
        log_[static_cast<std::size_t>(c) * kLog + logged_[c] % kLog] = roughMwOf(total);
        ++logged_[c];
        senseCell(c);
    }
}

void Reception::senseCell(std::int32_t cell) {
    if (cells_ == nullptr) return;
    const auto [begin, end] = cells_->members(cell);
    for (const Slot* r = begin; r != end; ++r) {
        if (cell_[*r] != cell) continue;  // not moved in yet (moveStations)
        const Units total = heard_[*r] + field_[cell];
        // Units first (no conversion); setSensedPower decides in mW as everywhere else.
        if ((total >= sensingUnits_) != static_cast<bool>(sensedBusy_[*r])) setSensedPower(*r, mwOf(total));
    }
}

void Reception::moveStations(const FarCells& cells) {
    cells_ = &cells;
    for (Slot r = 0; r < static_cast<Slot>(cell_.size()); ++r) {
        const std::int32_t c = cells.cellOf(r);
        if (c == cell_[r]) continue;
        if (c >= 0) growField(c);
        cell_[r] = c;
        setSensedPower(r, mwOf(heard_[r] + fieldAt(r)));
    }
}

void Reception::farEnds(const StepLinks& step) {
    // A fall never raises a decoding station's largest interference: no log.
    for (std::size_t k = 0; k < step.farCell.size(); ++k) {
        if (step.farUnits[k] == 0) continue;
        field_[step.farCell[k]] -= step.farUnits[k];
        senseCell(step.farCell[k]);
    }
}

void Reception::openSegment(Slot r) {
    const std::int32_t c = lockCell_[r];
    const Units near = heard_[r] - lockOwn_[r];
    segmentNearMw_[r] = roughMwOf(near);
    segmentFrom_[r] = logged_[c];
    lockedMaxMw_[r] = std::max(lockedMaxMw_[r], roughMwOf(near + field_[c]));
}

void Reception::closeSegment(Slot r) {
    const std::int32_t c = lockCell_[r];
    const std::uint64_t end = logged_[c];
    std::uint64_t from = segmentFrom_[r];
    if (from == end) return;  // the field did not rise: the segment's largest was taken at its opening
    if (end - from > kLog) {
        ++logOverflows_;
        from = end - kLog;
    }
    double largest = 0;
    const double* ring = &log_[static_cast<std::size_t>(c) * kLog];
    for (std::uint64_t k = from; k < end; ++k) largest = std::max(largest, ring[k % kLog]);
    lockedMaxMw_[r] = std::max(lockedMaxMw_[r], segmentNearMw_[r] + largest);
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
        setSensedPower(r, mwOf(hear(r, step.units[k]) + fieldAt(r)));
    }
    farStarts(step);
}

Reception::Units Reception::hear(Slot r, Units units) {
    const Units total = heard_[r] + units;
    if (locked_[r] != 0 && lockCell_[r] >= 0) {
        if (logged_[lockCell_[r]] != segmentFrom_[r]) closeSegment(r);
        heard_[r] = total;
        openSegment(r);
        return total;
    }
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
        lockCell_[r] = link.cell;
        if (link.cell >= 0) {
            growField(link.cell);
            lockedMaxMw_[r] = link.maxInterferenceMw;
            lockOwn_[r] = total - others;
            openSegment(r);
        }
    }
    setSensedPower(r, mwOf(total + fieldAt(r)));
}

double Reception::frameEnds(FrameId id, kernel::SimTime start, Link& link) {
    const Slot r = link.receiver;
    if (locked_[r] == id) {
        if (lockCell_[r] >= 0) {
            closeSegment(r);
            link.maxInterferenceMw = lockedMaxMw_[r];
        }
        locked_[r] = 0;
    }
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
