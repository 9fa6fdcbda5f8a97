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
      ratioDb_(linearToDb(settings.bandwidthHz / (settings.rateMbps * 1e6))),
      sensingUnits_(unitsOf(sensingMw_)) {}

double Reception::mwOf(Units units) { return static_cast<double>(units) / kUnitsPerMw; }

void Reception::addStation() { st_.emplace_back(); }

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
        if (st_[*r].cell != cell) continue;  // not moved in yet (moveStations)
        const Units total = st_[*r].heard + field_[cell];
        // Units first (no conversion); setSensedPower decides in mW as everywhere else.
        if ((total >= sensingUnits_) != static_cast<bool>(st_[*r].sensedBusy)) setSensedPower(*r, mwOf(total));
    }
}

void Reception::moveStations(const FarCells& cells) {
    cells_ = &cells;
    for (Slot r = 0; r < static_cast<Slot>(st_.size()); ++r) {
        const std::int32_t c = cells.cellOf(r);
        if (c == st_[r].cell) continue;
        if (c >= 0) growField(c);
        st_[r].cell = c;
        setSensedPower(r, mwOf(st_[r].heard + fieldAt(r)));
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
    const std::int32_t c = st_[r].lockCell;
    const Units near = st_[r].heard - st_[r].lockOwn;
    st_[r].segmentNearMw = roughMwOf(near);
    st_[r].segmentFrom = logged_[c];
    st_[r].lockedMaxMw = std::max(st_[r].lockedMaxMw, roughMwOf(near + field_[c]));
}

void Reception::closeSegment(Slot r) {
    const std::int32_t c = st_[r].lockCell;
    const std::uint64_t end = logged_[c];
    std::uint64_t from = st_[r].segmentFrom;
    if (from == end) return;  // the field did not rise: the segment's largest was taken at its opening
    if (end - from > kLog) {
        ++logOverflows_;
        from = end - kLog;
    }
    double largest = 0;
    const double* ring = &log_[static_cast<std::size_t>(c) * kLog];
    for (std::uint64_t k = from; k < end; ++k) largest = std::max(largest, ring[k % kLog]);
    st_[r].lockedMaxMw = std::max(st_[r].lockedMaxMw, st_[r].segmentNearMw + largest);
}

void Reception::startSending(Slot s, FrameId id, kernel::SimTime now) {
    st_[s].locked = 0;
    st_[s].sending = id;
    st_[s].sendStart = now;
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
        if (halfAtStart != nullptr && st_[r].sending != 0) halfAtStart->push_back(static_cast<std::uint32_t>(k));
        if (step.tier[k] == StepLinks::kBelowFloor) continue;
        setSensedPower(r, mwOf(hear(r, step.units[k]) + fieldAt(r)));
    }
    farStarts(step);
}

Reception::Units Reception::hear(Slot r, Units units) {
    const Units total = st_[r].heard + units;
    if (st_[r].locked != 0 && st_[r].lockCell >= 0) {
        if (logged_[st_[r].lockCell] != st_[r].segmentFrom) closeSegment(r);
        st_[r].heard = total;
        openSegment(r);
        return total;
    }
    st_[r].heard = total;
    if (st_[r].locked != 0) {
        Link& decoding = *st_[r].lockedLink;
        decoding.maxInterferenceMw = std::max(decoding.maxInterferenceMw, mwOf(total - unitsOf(decoding.powerMw)));
    }
    return total;
}

void Reception::linkStarts(FrameId id, Link& link) {
    const Slot r = link.receiver;
    if (st_[r].sending != 0) link.halfDuplex = true;
    if (link.powerMw < floorMw_) return;
    link.counted = true;
    const Units others = st_[r].heard;
    const bool decoding = st_[r].locked != 0;
    const Units total = hear(r, unitsOf(link.powerMw));
    if (!decoding && st_[r].sending == 0 && link.powerMw >= sensingMw_) {
        st_[r].locked = id;
        st_[r].lockedLink = &link;
        link.locked = true;
        link.maxInterferenceMw = mwOf(others);
        st_[r].lockCell = link.cell;
        if (link.cell >= 0) {
            growField(link.cell);
            st_[r].lockedMaxMw = link.maxInterferenceMw;
            st_[r].lockOwn = total - others;
            openSegment(r);
        }
    }
    setSensedPower(r, mwOf(total + fieldAt(r)));
}

double Reception::frameEnds(FrameId id, kernel::SimTime start, Link& link) {
    const Slot r = link.receiver;
    if (st_[r].locked == id) {
        if (st_[r].lockCell >= 0) {
            closeSegment(r);
            link.maxInterferenceMw = st_[r].lockedMaxMw;
        }
        st_[r].locked = 0;
    }
    if (!link.counted) return 0;
    if (sentSince(r, start)) link.halfDuplex = true;
    return leave(r, unitsOf(link.powerMw));
}

void Reception::setSensedPower(Slot s, double mw) {
    const bool busy = mw >= sensingMw_;
    if (busy == static_cast<bool>(st_[s].sensedBusy)) return;
    st_[s].sensedBusy = busy;
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
