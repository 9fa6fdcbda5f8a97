#include "sbsim/radio/DiscMedium.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "sbsim/radio/Receiver.h"

namespace sbsim::radio {

namespace {
/// A stream of its own, so radio losses never shift the storyboard's random draws.
constexpr unsigned kMediumStream = 0x7632'7800;
}  // namespace

DiscMedium::DiscMedium(DiscSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory)
    : Medium(std::move(directory)), settings_(settings), snapshot_(snapshot) {
    if (!(settings_.range > 0) || !std::isfinite(settings_.range))
        throw std::invalid_argument("V2X range must be > 0 m");
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

    const auto self = snapshot_.indexOf(sender);
    if (!self) return;  // not on the road (yet): nobody hears it
    if (gridTime_ != snapshot_.time()) {
        grid_.build(snapshot_, settings_.range);
        gridTime_ = snapshot_.time();
        receiverKnown_.clear();
        for (Neighbourhood& n : near_) n.known = false;
        near_.resize(snapshot_.ids().size());
    }
    if (receiverKnown_.empty() || receiversChanges_ != simulation().moduleChanges()) {
        receiverKnown_.assign(snapshot_.ids().size(), 0);
        receivers_.assign(snapshot_.ids().size(), nullptr);
        receiversChanges_ = simulation().moduleChanges();
    }
    const std::shared_ptr<const V2xMessage> shared(std::move(message));
    const auto& positions = snapshot_.positions();
    const kernel::SimTime now = simTime();
    if (trace() != nullptr) {
        TraceLine line;
        line.event = TraceLine::Event::Tx;
        line.t = now;
        line.message = shared.get();
        line.station = sender;
        line.seq = shared->sequence();
        line.x = positions(0, *self);
        line.y = positions(1, *self);
        trace()->record(line, now);
    }
    // With a trace, stations out to the trace range are visited too (to report them out of range);
    // the draws stay those of the stations in range, in the same ascending order.
    std::vector<Receiver*> receivers;
    std::vector<std::string> stations;
    Counts* counts = countsOf(*shared);
    const double radius = trace() != nullptr ? std::max(settings_.range, settings_.traceRange) : settings_.range;
    Neighbourhood& near = near_[*self];
    if (!near.known || near.radius != radius) {
        near.others = grid_.within(*self, radius);
        near.distance.resize(near.others.size());
        near.bin.resize(near.others.size());
        for (std::size_t k = 0; k < near.others.size(); ++k) {
            near.distance[k] = (positions.col(near.others[k]) - positions.col(*self)).norm();
            near.bin[k] = static_cast<std::uint32_t>(near.distance[k] / kDistanceBin);
        }
        near.known = true;
        near.radius = radius;
    }
    for (std::size_t k = 0; k < near.others.size(); ++k) {
        const auto other = near.others[k];
        if (!receiverKnown_[other]) {
            receivers_[other] = receivingSide(snapshot_.ids()[other]);
            receiverKnown_[other] = 1;
        }
        Receiver* receiver = receivers_[other];
        if (receiver == nullptr) continue;  // a vehicle without services
        const double distance = near.distance[k];
        const double p = receptionProbability(distance);
        std::optional<LossReason> loss;
        if (distance > settings_.range) {
            loss = LossReason::Range;
        } else if (p < 1.0 && !(random_->uniform01() < p)) {
            // Draw only where loss is possible, so a lossless medium consumes no random numbers.
            loss = LossReason::Fade;
        }
        if (distance <= settings_.range && counts != nullptr) {
            // Medium::countLink inline, with the bin computed once per step: this runs per link.
            const std::uint32_t bin = near.bin[k];
            if (counts->linkStations.size() <= bin) {
                counts->linkStations.resize(bin + 1);
                counts->linkReceptions.resize(bin + 1);
            }
            ++counts->linkStations[bin];
            if (!loss) ++counts->linkReceptions[bin];
        }
        if (trace() != nullptr && (!loss || distance <= settings_.traceRange)) {
            TraceLine line;
            line.event = loss ? TraceLine::Event::Lost : TraceLine::Event::Rx;
            line.t = loss ? now : now + settings_.latency;
            line.message = shared.get();
            line.station = snapshot_.ids()[other];
            line.sender = sender;
            line.seq = shared->sequence();
            line.distance = distance;
            line.delay = settings_.latency.seconds();
            if (loss) line.reason = *loss;
            trace()->record(line, now);
        }
        if (!loss) {
            receivers.push_back(receiver);
            stations.push_back(snapshot_.ids()[other]);
        }
    }
    deliverLater(shared, std::move(receivers), std::move(stations), settings_.latency);
}

}  // namespace sbsim::radio
