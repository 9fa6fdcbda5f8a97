#include "sbsim/radio/disc/DiscMedium.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "sbsim/radio/Receiver.h"

namespace sbsim::radio {

namespace {
/// A stream of its own, so radio losses never shift the storyboard's random draws.
constexpr unsigned kMediumStream = 0x7632'7800;
/// The kept neighbourhoods' skin, as a share of their radius: lists of 1.1² the disc's stations,
/// rebuilt when two vehicles together moved a tenth of the range (50 m of the default 500 m).
constexpr double kSkinShare = 0.1;
/// Kept lists serve while their epochs last this many steps (0.1 s steps: tens); else (1 s steps:
/// one or two) each sender's neighbours come from the step's grid.
constexpr std::uint64_t kLastingUpdates = 4;

double checkedRange(double range) {
    if (!(range > 0) || !std::isfinite(range)) throw std::invalid_argument("V2X range must be > 0 m");
    return range;
}
}  // namespace

DiscMedium::DiscMedium(DiscSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory)
    : Medium(std::move(directory)), settings_(settings), bins_(checkedRange(settings.range)), snapshot_(snapshot) {
    if (settings_.latency < kernel::SimTime::zero()) throw std::invalid_argument("V2X latency must be >= 0 s");
    if (settings_.fadeStart && (*settings_.fadeStart < 0 || *settings_.fadeStart > settings_.range)) {
        throw std::invalid_argument("V2X fade start must be between 0 m and the range");
    }
}

void DiscMedium::initialize() { random_ = simulation().randomStream(kMediumStream); }

double DiscMedium::receptionProbability(double distance) const {
    if (distance > settings_.range) return 0.0;
    if (!settings_.fadeStart || distance <= *settings_.fadeStart) return 1.0;
    return (settings_.range - distance) / (settings_.range - *settings_.fadeStart);
}

void DiscMedium::broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message) {
    if (!message) throw std::invalid_argument("cannot send a null V2X message");
    stamp(*message, sender);

    const FixedStations& fixed = fixedStations();
    if (idsVersion_ != snapshot_.idsVersion()) {
        // The snapshot's ids interned in its order (ascending indices for the certificate
        // policy's tables) when they change, not per step; and each station's place in them, so a
        // frame finds its sender by the index stamp() looked up, not by a search among the names.
        idsVersion_ = snapshot_.idsVersion();
        const auto& ids = snapshot_.ids();
        slots_.clear();  // set afresh for the new indices
        previousIndices_.swap(stationIndices_);
        stationIndices_.resize(ids.size());
        for (std::size_t i = 0; i < ids.size(); ++i) stationIndices_[i] = stationIndex(ids[i]);
        snapshotIndices_.assign(
            stationIndices_.empty() ? 0 : *std::max_element(stationIndices_.begin(), stationIndices_.end()) + 1,
            kNotInSnapshot);
        for (std::size_t i = 0; i < ids.size(); ++i)
            snapshotIndices_[stationIndices_[i]] = static_cast<traffic::VehicleSnapshot::Index>(i);
        // The neighbourhoods of vehicles gone (for now) are freed: memory follows the vehicles alive.
        for (const StationIndex gone : previousIndices_) {
            if (gone < near_.size() && (gone >= snapshotIndices_.size() || snapshotIndices_[gone] == kNotInSnapshot))
                near_[gone] = Neighbourhood{};
        }
    }
    const StationIndex senderIndex = Medium::senderIndex(*message);
    const auto self = senderIndex < snapshotIndices_.size() && snapshotIndices_[senderIndex] != kNotInSnapshot
                          ? std::optional<traffic::VehicleSnapshot::Index>(snapshotIndices_[senderIndex])
                          : std::nullopt;
    const auto fixedSelf = self ? std::nullopt : fixed.indexOf(sender);
    if (!self && !fixedSelf) return;  // not on the road (yet): nobody hears it
    if (gridTime_ != snapshot_.time()) {
        gridTime_ = snapshot_.time();
        ++step_;
        gridBuilt_ = false;
    }
    while (fixedIndices_.size() < static_cast<std::size_t>(fixed.size()))
        fixedIndices_.push_back(stationIndex(fixed.ids()[fixedIndices_.size()]));
    if (slots_.empty() || receiversChanges_ != receiverChanges()) {
        slots_.resize(stationIndices_.size());
        for (std::size_t i = 0; i < slots_.size(); ++i) slots_[i] = Slot{nullptr, stationIndices_[i], false};
        receiversChanges_ = receiverChanges();
    }
    const std::shared_ptr<const V2xMessage> shared(std::move(message));
    const auto& positions = snapshot_.positions();
    const Eigen::Vector2d from = self ? Eigen::Vector2d(positions.col(*self)) : fixed.positions().col(*fixedSelf);
    const kernel::SimTime now = simTime();
    if (trace() != nullptr) {
        TraceLine line;
        line.event = TraceLine::Event::Tx;
        line.t = now;
        line.message = shared.get();
        line.station = sender;
        line.seq = shared->sequence();
        line.x = from.x();
        line.y = from.y();
        trace()->record(line, now);
    }
    // With a trace, stations out to the trace range are visited too (to report them out of range);
    // the draws stay those of the stations in range, in the same ascending order.
    Receivers receivers;
    std::vector<StationIndex> stations;
    Counts* counts = countsOf(*shared);
    // Every station in range receives, nothing traced: a frame takes its sender's receivers of the step.
    const bool everyoneInRange = trace() == nullptr && !settings_.fadeStart;
    std::shared_ptr<const Recipients> shareable;  // then the vehicles' receivers, as the step's
    const double radius = trace() != nullptr ? std::max(settings_.range, settings_.traceRange) : settings_.range;
    const auto consider = [&](Receiver* receiver, StationIndex index, const std::string& station, double distance) {
        if (receiver == nullptr) return;  // a vehicle without services
        const double p = receptionProbability(distance);
        std::optional<LossReason> loss;
        if (distance > settings_.range) {
            loss = LossReason::Range;
        } else if (p < 1.0 && !(random_->uniform01() < p)) {
            // Draw only where loss is possible, so a lossless medium consumes no random numbers.
            loss = LossReason::Fade;
        }
        if (distance <= settings_.range && counts != nullptr) countLink(*counts, distance, !loss);
        if (trace() != nullptr && (!loss || distance <= settings_.traceRange)) {
            TraceLine line;
            line.event = loss ? TraceLine::Event::Lost : TraceLine::Event::Rx;
            line.t = loss ? now : now + settings_.latency;
            line.message = shared.get();
            line.station = station;
            line.sender = sender;
            line.seq = shared->sequence();
            line.distance = distance;
            line.delay = settings_.latency.seconds();
            if (loss) line.reason = *loss;
            trace()->record(line, now);
        }
        if (!loss) {
            receivers.push_back(receiver);
            stations.push_back(index);
        }
    };
    const auto vehicleReceiver = [&](traffic::VehicleSnapshot::Index other) {
        Slot& slot = slots_[static_cast<std::size_t>(other)];
        if (!slot.known) {
            slot.receiver = receivingSide(slot.station, snapshot_.ids()[other]);
            slot.known = true;
        }
        return slot.receiver;
    };
    // Vehicles first, ascending, then the stationary stations in the order they were added.
    if (self) {
        if (near_.size() <= senderIndex) near_.resize(senderIndex + 1);
        Neighbourhood& near = near_[senderIndex];
        if (near.step != step_ || near.radius != radius) {
            if (!kept_ || kept_->radius() != radius) kept_.emplace(radius, radius * kSkinShare);
            if (keptStep_ != step_ || kept_->epochs() == 0) {
                kept_->update(positions, stationIndices_, keptIdsVersion_ != idsVersion_);
                keptStep_ = step_;
                keptIdsVersion_ = idsVersion_;
            }
            near.others.clear();
            near.squared.clear();
            if (kept_->lasting(kLastingUpdates)) {
                kept_->within(*self, near.others, near.squared);
            } else {
                // The grid's answer as a bit set read in ascending order, with the grid test's own squares.
                buildGrid();
                const auto n = static_cast<std::size_t>(positions.cols());
                const std::size_t words = (n + 63) / 64;
                if (marks_.size() != words) marks_.assign(words, 0);
                if (squared_.size() < n) squared_.resize(n);
                grid_.markWithin(*self, radius, marks_.data(), squared_.data());
                for (std::size_t w = 0; w < words; ++w) {
                    for (std::uint64_t bits = marks_[w]; bits != 0; bits &= bits - 1) {
                        const std::size_t j = w * 64 + static_cast<std::size_t>(std::countr_zero(bits));
                        near.others.push_back(static_cast<traffic::NeighbourGrid::Index>(j));
                        near.squared.push_back(squared_[j]);
                    }
                    marks_[w] = 0;
                }
            }
            near.step = step_;
            near.radius = radius;
            near.receiversKnown = false;
        }
        if (everyoneInRange) {
            if (!near.receiversKnown || near.receiversChanges != receiversChanges_) takeReceivers(senderIndex, near);
            shareable = near.recipients;
            if (counts != nullptr && !near.perBin.empty()) {
                if (counts->linkStations.size() < near.perBin.size()) {
                    counts->linkStations.resize(near.perBin.size());
                    counts->linkReceptions.resize(near.perBin.size());
                }
                for (std::size_t b = 0; b < near.perBin.size(); ++b) {
                    counts->linkStations[b] += near.perBin[b];
                    counts->linkReceptions[b] += near.perBin[b];
                }
            }
        }
        for (std::size_t k = 0; !everyoneInRange && k < near.others.size(); ++k) {
            const auto other = near.others[k];
            consider(vehicleReceiver(other), stationIndices_[other], snapshot_.ids()[other],
                     std::sqrt(near.squared[k]));
        }
    } else {
        // A roadside unit sends about once a second: its neighbours are looked up afresh.
        buildGrid();
        for (const auto other : grid_.around(from.x(), from.y(), radius)) {
            consider(vehicleReceiver(other), stationIndices_[other], snapshot_.ids()[other],
                     (positions.col(other) - from).norm());
        }
    }
    fixed.forEachWithin(from, radius, fixedSelf, [&](FixedStations::Index k, double distance) {
        consider(receivingSide(fixedIndices_[k], fixed.ids()[k]), fixedIndices_[k], fixed.ids()[k], distance);
    });
    if (shareable != nullptr) {
        if (receivers.empty()) return deliverLater(shared, std::move(shareable), settings_.latency);
        // Stationary stations in range: after the vehicles, in a list of the frame's own.
        receivers.insert(receivers.begin(), shareable->receivers.begin(), shareable->receivers.end());
        stations.insert(stations.begin(), shareable->stations.begin(), shareable->stations.end());
    }
    deliverLater(shared, std::move(receivers), std::move(stations), settings_.latency);
}

void DiscMedium::buildGrid() {
    if (gridBuilt_) return;
    // Cells of a quarter of the range: a neighbourhood scans about 1.6 times its disc, where cells
    // of the range scan nearly three times it.
    grid_.build(snapshot_, settings_.range / 4);
    gridBuilt_ = true;
}

void DiscMedium::takeReceivers(StationIndex sender, Neighbourhood& near) {
    Receivers& receivers = scratch_.receivers;
    std::vector<StationIndex>& stations = scratch_.stations;
    // Counted per bin in a small array while the range has few bins (no growth check per link).
    constexpr std::size_t kFewBins = 64;
    std::array<std::uint64_t, kFewBins> few{};
    const bool fewBins = settings_.range / kDistanceBin < kFewBins - 1;
    near.perBin.clear();
    // One pass over the neighbours: range and bin from the square (no root), receiver and station
    // from one record per vehicle, written through pointers held in registers (a push_back's
    // stores would make the compiler reload the vectors' ends, and the tables, at every link).
    const std::size_t n = near.others.size();
    receivers.resize(n);
    stations.resize(n);
    Receiver** const toReceiver = receivers.data();
    StationIndex* const toStation = stations.data();
    std::size_t taken = 0;
    const KeptNeighbourhoods::Index* const others = near.others.data();
    const double* const squares = near.squared.data();
    Slot* const slots = slots_.data();
    const SquaredDistanceBins::Lookup binOf = bins_.lookup();
    const double maxSquared = bins_.maxSquared();
    for (std::size_t k = 0; k < n; ++k) {
        const double squared = squares[k];
        if (squared > maxSquared) continue;  // beyond the range
        Slot& slot = slots[others[k]];
        if (!slot.known) {
            slot.receiver = receivingSide(slot.station, snapshot_.ids()[static_cast<std::size_t>(others[k])]);
            slot.known = true;
        }
        Receiver* const receiver = slot.receiver;
        if (receiver == nullptr) continue;  // a vehicle without services
        toReceiver[taken] = receiver;
        toStation[taken] = slot.station;
        ++taken;
        if (!(squared >= 0)) continue;  // as Medium::countLink
        const std::size_t bin = binOf.of(squared);
        if (fewBins && bin < kFewBins) {
            ++few[bin];
            continue;
        }
        if (near.perBin.size() <= bin) near.perBin.resize(bin + 1);
        ++near.perBin[bin];
    }
    receivers.resize(taken);
    stations.resize(taken);
    if (fewBins) {
        std::size_t bins = kFewBins;
        while (bins > 0 && few[bins - 1] == 0) --bins;
        if (near.perBin.size() < bins) near.perBin.resize(bins);
        for (std::size_t b = 0; b < bins; ++b) near.perBin[b] += few[b];
    }
    near.receiversKnown = true;
    // The last list's receivers were looked up while no station's module changed since
    // (Medium::receiverChanges()): the same stations are then the same receivers.
    const bool sameModules = near.receiversChanges == receiversChanges_;
    near.receiversChanges = receiversChanges_;
    // The same receivers as the sender's last list: that list again (the certificate policy then
    // walks nothing). The comparison is the sender's table's own split of the two lists, which it
    // takes when this list's frames come instead of matching them again. Else a new list, unless
    // nobody else holds the last (frames on the air, the policy) and it can be refilled in place.
    std::shared_ptr<Recipients> last = near.recipients;
    if (last != nullptr && certificates().sameList(sender, last->stations, stations) &&
        (sameModules || last->receivers == receivers))
        return;
    if (last == nullptr || last.use_count() > 2) {  // held elsewhere than here and in `last`
        near.recipients = std::make_shared<Recipients>();
        near.recipients->receivers.reserve(receivers.size());
        near.recipients->stations.reserve(stations.size());
    } else {
        last.reset();  // refilled in place: no list to split against
    }
    near.recipients->receivers.swap(receivers);
    near.recipients->stations.swap(stations);
    if (last != nullptr) {
        certificates().expectList(sender, LastHeard::List(last, &last->stations),
                                  LastHeard::List(near.recipients, &near.recipients->stations));
    }
}

}  // namespace sbsim::radio
