#include "sbsim/radio/ChannelMedium.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Decibels.h"
#include "sbsim/radio/Receiver.h"

namespace sbsim::radio {

namespace {
enum TimerKind { kAccess = 1, kEnd = 2, kLoad = 3 };
/// A neighbourhood is hundreds of links: a few stations make a chunk worth a worker's wake-up.
constexpr std::size_t kStationsPerChunk = 4;

double toMw(double dbm) { return dbToLinear(dbm); }
double toDb(double mw) { return linearToDb(mw); }
}  // namespace

struct ChannelMedium::Link {
    Slot receiver = -1;
    std::uint32_t bin = 0;  // distance / kDistanceBin, for the link counts
    double distance = 0;
    double powerDbm = 0;
    double powerMw = 0;
    double maxInterferenceMw = 0;  // the largest sum of the other frames overlapping this one
    bool counted = false;          // above the floor: part of the receiver's sensed power
    bool halfDuplex = false;       // the receiver transmitted during the frame
    bool locked = false;           // the receiver was decoding this frame
};

struct ChannelMedium::StationTimer : kernel::Message {
    explicit StationTimer(Slot s) : kernel::Message("channel access", kAccess), station(s) {}
    Slot station;
};

struct ChannelMedium::EndTimer : kernel::Message {
    explicit EndTimer(std::uint64_t id) : kernel::Message("transmission end", kEnd), tx(id) {}
    std::uint64_t tx;
};

struct ChannelMedium::Transmission {
    explicit Transmission(std::uint64_t i) : id(i), end(i) {}
    std::uint64_t id;  // set again with end.tx when a spare is reused
    Slot sender = -1;
    std::shared_ptr<const V2xMessage> message;
    kernel::SimTime start;
    std::vector<Link> links;  // ascending receiver slot
    EndTimer end;
};

ChannelMedium::ChannelMedium(ChannelSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory,
                             std::shared_ptr<const Obstacles> obstacles)
    : Medium(std::move(directory)),
      settings_(std::move(settings)),
      snapshot_(snapshot),
      obstacles_(std::move(obstacles)),
      fer_((settings_.validate(), settings_.ferTable)) {
    pathLoss_ = settings_.makePathLoss();
    setSecured(settings_.secured);
    fading_.m = settings_.nakagamiM;
    fading_.veinsDistanceRule = settings_.fading == ChannelSettings::Fading::NakagamiVeins;
    sensingMw_ = toMw(settings_.sensingDbm);
    noiseMw_ = toMw(settings_.noiseDbm);
    floorMw_ = toMw(settings_.interferenceFloorDbm);
    // The cutoff: where the mean power plus a margin for shadowing (2 σ) and fading falls below
    // the floor. Path loss grows with distance, so double, then bisect.
    const double margin =
        2 * settings_.shadowingSigmaDb + (settings_.fading == ChannelSettings::Fading::None ? 0.0 : 5.0);
    const auto above = [&](double d) { return meanPowerDbm(d) + margin >= settings_.interferenceFloorDbm; };
    double lo = 1;
    double hi = 2;
    while (above(hi) && hi < 1e5) {
        lo = hi;
        hi *= 2;
    }
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (above(mid) ? lo : hi) = mid;
    }
    cutoff_ = hi;
}

ChannelMedium::~ChannelMedium() = default;

double ChannelMedium::meanPowerDbm(double distance) const { return settings_.powerDbm - pathLoss_->lossDb(distance); }

void ChannelMedium::initialize() {
    seed_ = simulation().seed();
    if (settings_.shadowingSigmaDb > 0 && settings_.shadowingCorrelation > 0) {
        shadowing_ =
            std::make_unique<CorrelatedShadowing>(settings_.shadowingSigmaDb, settings_.shadowingCorrelation, seed_);
    }
    loadTimer_ = std::make_unique<kernel::Message>("channel load", kLoad);
    scheduleAt(DccStateMachine::kSampling * (simTime() / DccStateMachine::kSampling + 1), *loadTimer_);
}

void ChannelMedium::handleMessage(kernel::Message& msg) {
    switch (msg.kind()) {
        case kAccess:
            return startTransmission(static_cast<StationTimer&>(msg).station);
        case kEnd:
            return endTransmission(static_cast<EndTimer&>(msg).tx);
        case kLoad:
            sampleLoad();
            return scheduleAfter(DccStateMachine::kSampling, msg);
        default:
            return Medium::handleMessage(msg);
    }
}

ChannelMedium::Slot ChannelMedium::stationOf(const std::string& id) {
    if (const auto it = slotOf_.find(id); it != slotOf_.end()) return it->second;
    const auto s = static_cast<Slot>(ids_.size());
    slotOf_.emplace(id, s);
    ids_.push_back(id);
    keys_.push_back(CounterRandom::keyOf(id));
    x_.push_back(0);
    y_.push_back(0);
    present_.push_back(0);
    sensedMw_.push_back(0);
    sensedBusy_.push_back(0);
    transmitting_.push_back(0);
    locked_.push_back(0);
    incoming_.emplace_back();
    cbrBusy_.push_back(0);
    cbrSince_.push_back(simTime());
    windowStart_.push_back(simTime());
    busyNs_.push_back(0);
    cbr_.push_back(0);
    dcc_.emplace_back();
    queue_.emplace_back();
    contending_.push_back(0);
    backoff_.push_back(0);
    countStart_.push_back(simTime());
    idleSince_.push_back(kernel::SimTime::zero());
    timers_.push_back(std::make_unique<StationTimer>(s));
    sentInStep_.push_back(0);
    receiver_.push_back(nullptr);
    near_.emplace_back();
    return s;
}

void ChannelMedium::refreshStations() {
    if (refreshedAt_ == snapshot_.time() && slotOfIndex_.size() == static_cast<std::size_t>(snapshot_.size())) return;
    refreshedAt_ = snapshot_.time();
    std::fill(present_.begin(), present_.end(), 0);
    std::fill(receiver_.begin(), receiver_.end(), nullptr);
    slotOfIndex_.assign(static_cast<std::size_t>(snapshot_.size()), -1);
    const auto& positions = snapshot_.positions();
    for (traffic::VehicleSnapshot::Index i = 0; i < snapshot_.size(); ++i) {
        const std::string& id = snapshot_.ids()[i];
        Slot s = -1;
        if (const auto it = slotOf_.find(id); it != slotOf_.end()) {
            s = it->second;
        } else if (receiverOf(id) != nullptr) {
            s = stationOf(id);
        } else {
            continue;  // a vehicle without services is no station
        }
        slotOfIndex_[i] = s;
        present_[s] = 1;
        // Looked up once a step, not once a link: modules come and go only with SUMO's steps.
        receiver_[s] = receivingSide(id);
        x_[s] = positions(0, i);
        y_[s] = positions(1, i);
    }
    // Stationary stations stay where they are; they are stations once their module exists.
    const FixedStations& fixed = fixedStations();
    for (FixedStations::Index k = 0; k < fixed.size(); ++k) {
        const std::string& id = fixed.ids()[k];
        if (slotOf_.count(id) == 0 && receiverOf(id) == nullptr) continue;
        const Slot s = stationOf(id);
        present_[s] = 1;
        receiver_[s] = receivingSide(id);
        x_[s] = fixed.positions()(0, k);
        y_[s] = fixed.positions()(1, k);
    }
    // A station that left keeps its slot (frames may still be on the air) but not its
    // neighbourhood: a long run sees tens of thousands of vehicles.
    for (Slot s = 0; s < static_cast<Slot>(near_.size()); ++s) {
        if (!present_[s] && near_[s].at) near_[s] = Neighbourhood{};
    }
    // Cells of half the cutoff: a query touches about 5x5 cells around the sender.
    grid_.build(snapshot_, std::max(cutoff_ / 2, 1.0));
}

void ChannelMedium::broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message) {
    if (!message) throw std::invalid_argument("cannot send a null V2X message");
    stamp(*message, sender);
    refreshStations();
    const auto index = snapshot_.indexOf(sender);
    const auto fixed = index ? std::nullopt : fixedStations().indexOf(sender);
    if (!index && !fixed) return;  // not on the road (yet): nobody hears it
    const Slot s = stationOf(sender);
    if (!present_[s]) {
        present_[s] = 1;  // a station whose directory entry appeared after the last refresh
        const Eigen::Vector2d at =
            index ? Eigen::Vector2d(snapshot_.positions().col(*index)) : fixedStations().positions().col(*fixed);
        x_[s] = at.x();
        y_[s] = at.y();
    }
    std::shared_ptr<const V2xMessage> shared(std::move(message));
    if (queue_[s].size() >= settings_.queueLimit) {
        if (trace() != nullptr) {
            TraceLine line;
            line.event = TraceLine::Event::Lost;
            line.t = simTime();
            line.message = shared.get();
            line.station = ids_[s];
            line.sender = ids_[s];
            line.seq = shared->sequence();
            line.reason = LossReason::Queue;
            trace()->record(line, simTime());
        }
        return;
    }
    queue_[s].push_back({std::move(shared)});
    if (!contending_[s] && transmitting_[s] == 0 && queue_[s].size() == 1) startAccess(s);
}

void ChannelMedium::startAccess(Slot s) {
    const V2xMessage& head = *queue_[s].front().message;
    CounterRandom random(seed_, keys_[s], head.sequence(), 0, DrawPurpose::Backoff);
    backoff_[s] = static_cast<std::int32_t>(random.uniform01() * (settings_.contentionWindow + 1));
    contending_[s] = 1;
    if (!sensedBusy_[s]) scheduleCountdown(s);
}

void ChannelMedium::scheduleCountdown(Slot s) {
    // The backoff counts down once the channel has been idle for AIFS.
    countStart_[s] = std::max(simTime(), idleSince_[s] + settings_.aifs());
    scheduleAt(countStart_[s] + settings_.slot * backoff_[s], *timers_[s]);
}

void ChannelMedium::setSensedPower(Slot s, double mw) {
    sensedMw_[s] = mw;
    const bool busy = mw >= sensingMw_;
    if (busy == static_cast<bool>(sensedBusy_[s])) return;
    sensedBusy_[s] = busy;
    if (busy) {
        // Freeze the backoff: the slots that passed idle are spent. A station whose backoff ends
        // now sends anyway: carrier sense takes part of a slot, so frames starting in the same
        // slot collide, as on the air.
        if (contending_[s] && timers_[s]->isScheduled() && timers_[s]->arrivalTime() > simTime()) {
            cancelEvent(*timers_[s]);
            if (simTime() > countStart_[s]) {
                const auto spent = static_cast<std::int32_t>((simTime() - countStart_[s]) / settings_.slot);
                backoff_[s] = std::max(0, backoff_[s] - spent);
            }
        }
    } else {
        idleSince_[s] = simTime();
        if (contending_[s]) scheduleCountdown(s);
    }
    setCbrBusy(s);
}

void ChannelMedium::setCbrBusy(Slot s) {
    // The channel counts busy for the busy ratio while sensed busy or while the station sends.
    const bool busy = sensedBusy_[s] || transmitting_[s] != 0;
    if (busy == static_cast<bool>(cbrBusy_[s])) return;
    if (!busy) busyNs_[s] += (simTime() - cbrSince_[s]).raw();
    cbrBusy_[s] = busy;
    cbrSince_[s] = simTime();
}

void ChannelMedium::computeLinks(Slot s, const Transmission& tx, std::vector<Link>& links) {
    // Who is in range, how far, and the mean power (path loss and obstacles) stay the same for
    // all of a sender's frames within one SUMO step: computed once per step, for the likely
    // senders of the step together at its first frame (prepareStep), else at the sender's first.
    if (batchedAt_ != refreshedAt_) prepareStep(s);
    Neighbourhood& near = near_[s];
    if (near.at != refreshedAt_) computeNeighbourhood(s);
    if (sentInStep_[s] != step_) {
        sentInStep_[s] = step_;
        sentThisStep_.push_back(s);
    }
    links.resize(near.receivers.size());
    const std::uint64_t frameKey = CounterRandom::frameKey(seed_, keys_[s], tx.message->sequence());
    const bool fading = settings_.fading != ChannelSettings::Fading::None;
    const bool shadowing = settings_.shadowingSigmaDb > 0;
    if (shadowing_) {
        // The pairs are looked up (and made) here, serially; the pool then moves distinct pairs on.
        shadowing_->pairs(keys_[s], near.key, simTime(), pairs_);
    }
    // Each link is a pure function of its ends and its key: any split over threads gives the same.
    simulation().parallel().run(
        near.receivers.size(),
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t k = begin; k < end; ++k) {
                const Slot r = near.receivers[k];
                // Field by field: `link = Link{}` went through a stack temporary whose overlapping
                // stores stalled store-to-load forwarding (a quarter of this loop's time).
                Link& link = links[k];
                link.receiver = r;
                link.distance = near.distance[k];
                link.bin = near.bin[k];
                link.maxInterferenceMw = 0;
                link.counted = false;
                link.halfDuplex = false;
                link.locked = false;
                double dbm = near.meanDbm[k];
                if (shadowing_) {
                    if (k + 4 < end) shadowing_->prefetch(pairs_[k + 4]);
                    dbm += shadowing_->valueDb(pairs_[k], keys_[s], x_[s], y_[s], near.key[k], x_[r], y_[r]);
                } else if (shadowing) {
                    auto random = CounterRandom::ofFrame(frameKey, near.key[k], DrawPurpose::Shadowing);
                    dbm += settings_.shadowingSigmaDb * random.normal();
                }
                if (fading) {
                    auto random = CounterRandom::ofFrame(frameKey, near.key[k], DrawPurpose::Fading);
                    dbm += fading_.gainDb(link.distance, random);
                }
                link.powerDbm = dbm;
                link.powerMw = toMw(dbm);
            }
        },
        settings_.linksPerChunk);
    linksComputed_ += links.size();
}

void ChannelMedium::prepareStep(Slot first) {
    batchedAt_ = refreshedAt_;
    ++step_;
    // The stations that sent during the last step most likely send again in this one (a beacon
    // or CAM sends every step or more often): their neighbourhoods in one round on the pool. A
    // neighbourhood is a pure function of the snapshot, so which ones are computed here changes
    // nothing but the time.
    batch_.clear();
    for (const Slot t : sentThisStep_) {
        if (present_[t] && t != first) batch_.push_back(t);
    }
    batch_.push_back(first);
    sentThisStep_.clear();
    simulation().parallel().run(
        batch_.size(),
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t k = begin; k < end; ++k) computeNeighbourhood(batch_[k]);
        },
        kStationsPerChunk);
}

void ChannelMedium::computeNeighbourhood(Slot s) {
    Neighbourhood& near = near_[s];
    near.at = refreshedAt_;
    near.receivers.clear();
    const auto index = snapshot_.indexOf(ids_[s]);
    // The grid's order (by cell, then vehicle index) is the same whatever the thread count,
    // so the receivers need no sorting; the stationary stations follow in their own order.
    const auto take = [&](traffic::VehicleSnapshot::Index j) {
        if (const Slot r = slotOfIndex_[j]; r >= 0 && r != s) near.receivers.push_back(r);
    };
    const FixedStations& fixed = fixedStations();
    const auto fixedSelf = index ? std::nullopt : fixed.indexOf(ids_[s]);
    if (index) {
        grid_.forEachWithin(*index, cutoff_, take);
    } else if (fixedSelf) {
        grid_.forEachAround(x_[s], y_[s], cutoff_, take);
    }
    if ((index || fixedSelf) && !fixed.empty()) {
        fixed.forEachWithin({x_[s], y_[s]}, cutoff_, fixedSelf, [&](FixedStations::Index k, double) {
            const auto it = slotOf_.find(fixed.ids()[k]);
            if (it != slotOf_.end() && present_[it->second]) near.receivers.push_back(it->second);
        });
    }
    const std::size_t n = near.receivers.size();
    near.distance.resize(n);
    near.meanDbm.resize(n);
    near.key.resize(n);
    near.bin.resize(n);
    const Eigen::Vector2d from(x_[s], y_[s]);
    const bool obstacles = obstacles_ && obstacles_->size() > 0;
    for (std::size_t k = 0; k < n; ++k) {
        const Slot r = near.receivers[k];
        const Eigen::Vector2d to(x_[r], y_[r]);
        near.distance[k] = (to - from).norm();
        double mean = settings_.powerDbm - pathLoss_->lossDb(near.distance[k]);
        if (obstacles) mean -= obstacles_->lossDb(from, to);
        near.meanDbm[k] = mean;
        near.key[k] = keys_[r];
        near.bin[k] = static_cast<std::uint32_t>(near.distance[k] / kDistanceBin);
    }
}

void ChannelMedium::startTransmission(Slot s) {
    refreshStations();
    contending_[s] = 0;
    std::unique_ptr<Transmission> tx;
    if (spare_.empty()) {
        tx = std::make_unique<Transmission>(nextTx_);
    } else {
        tx = std::move(spare_.back());
        spare_.pop_back();
        tx->id = nextTx_;
        tx->end.tx = nextTx_;
        tx->links.clear();
    }
    ++nextTx_;
    tx->sender = s;
    tx->message = std::move(queue_[s].front().message);
    queue_[s].pop_front();
    tx->start = simTime();
    ++transmissions_;
    if (trace() != nullptr) {
        TraceLine line;
        line.event = TraceLine::Event::Tx;
        line.t = simTime();
        line.message = tx->message.get();
        line.station = ids_[s];
        line.seq = tx->message->sequence();
        line.x = x_[s];
        line.y = y_[s];
        line.cbr = cbr_[s];
        trace()->record(line, simTime());
    }
    if (present_[s]) computeLinks(s, *tx, tx->links);

    // The sender stops receiving: whatever it was receiving is lost to half-duplex.
    for (const Incoming& in : incoming_[s]) in.tx->links[in.link].halfDuplex = true;
    locked_[s] = 0;
    transmitting_[s] = tx->id;
    setCbrBusy(s);

    // Receivers one by one, in slot order: this part schedules events and must stay sequential.
    for (std::uint32_t k = 0; k < tx->links.size(); ++k) {
        Link& link = tx->links[k];
        const Slot r = link.receiver;
        if (transmitting_[r] != 0) link.halfDuplex = true;
        if (link.powerMw < floorMw_) continue;
        link.counted = true;
        std::vector<Incoming>& in = incoming_[r];
        double others = 0;
        for (const Incoming& e : in) others += e.mw;
        link.maxInterferenceMw = others;
        const double total = others + link.powerMw;
        for (const Incoming& e : in) {
            Link& old = e.tx->links[e.link];
            old.maxInterferenceMw = std::max(old.maxInterferenceMw, std::max(0.0, total - e.mw));
        }
        if (transmitting_[r] == 0 && locked_[r] == 0 && link.powerMw >= sensingMw_) {
            locked_[r] = tx->id;
            link.locked = true;
        }
        in.push_back({tx.get(), k, link.powerMw});
        setSensedPower(r, total);
    }
    scheduleAt(simTime() + settings_.airtime(tx->message->frameBytes()), tx->end);
    active_.emplace(tx->id, std::move(tx));
}

void ChannelMedium::endTransmission(std::uint64_t id) {
    const auto found = active_.find(id);
    if (found == active_.end()) return;
    std::unique_ptr<Transmission> tx = std::move(found->second);
    active_.erase(found);
    const V2xMessage& message = *tx->message;
    const double delay = (simTime() - message.sentAt()).seconds();
    const double ratioDb = toDb(settings_.bandwidthHz / (settings_.rateMbps * 1e6));
    refreshStations();  // the receivers' modules as of the last step
    Counts* counts = countsOf(message);
    const std::uint64_t frameKey = CounterRandom::frameKey(seed_, keys_[tx->sender], message.sequence());
    // Receptions without a drawn delay share one kernel event (in receiver order, as their own
    // events would have run); a drawn delay gives each its own.
    const bool drawnDelay = settings_.extraDelay == ChannelSettings::ExtraDelay::Uniform ||
                            settings_.extraDelay == ChannelSettings::ExtraDelay::Gamma;
    std::vector<Receiver*> receivers;
    std::vector<std::string> stations;
    const kernel::SimTime sharedDelay = settings_.extraDelay == ChannelSettings::ExtraDelay::Constant
                                            ? kernel::SimTime::fromSeconds(settings_.delay)
                                            : kernel::SimTime::zero();
    const auto flush = [&] {
        deliverLater(tx->message, std::move(receivers), std::move(stations), sharedDelay);
        receivers.clear();
        stations.clear();
    };

    for (Link& link : tx->links) {
        const Slot r = link.receiver;
        if (link.counted) {
            std::vector<Incoming>& in = incoming_[r];
            in.erase(std::remove_if(in.begin(), in.end(), [&](const Incoming& e) { return e.tx == tx.get(); }),
                     in.end());
            double total = 0;  // summed afresh, so no rounding drift accumulates
            for (const Incoming& e : in) total += e.mw;
            // A station that senses the channel free may schedule its backoff's end, possibly at
            // a delivery's time: the receptions so far go first, as their own events did.
            if (contending_[r] && (total >= sensingMw_) != static_cast<bool>(sensedBusy_[r])) flush();
            setSensedPower(r, total);
        }
        if (locked_[r] == id) locked_[r] = 0;

        std::optional<LossReason> loss;
        double sinrDb = 0;
        if (link.halfDuplex) {
            loss = LossReason::HalfDuplex;
        } else if (link.powerMw < sensingMw_) {
            loss = LossReason::Sensing;
        } else if (!link.locked) {
            loss = LossReason::Collision;  // the receiver was decoding another frame
        } else {
            sinrDb = toDb(link.powerMw / (noiseMw_ + link.maxInterferenceMw));
            const double snrDb = toDb(link.powerMw / noiseMw_);
            const double ferWith = fer_.ferAtEbN0Db(sinrDb + ratioDb);
            const double ferWithout = fer_.ferAtEbN0Db(snrDb + ratioDb);
            auto random = CounterRandom::ofFrame(frameKey, keys_[r], DrawPurpose::Decode);
            const double u = random.uniform01();
            if (u < ferWithout) {
                loss = LossReason::Propagation;
            } else if (u < ferWith) {
                loss = LossReason::Collision;
            }
        }
        Receiver* receiver = receiver_[r];
        if (counts != nullptr) {
            // Medium::countLink inline, the bin computed once per step: this runs per link.
            if (counts->linkStations.size() <= link.bin) {
                counts->linkStations.resize(link.bin + 1);
                counts->linkReceptions.resize(link.bin + 1);
            }
            ++counts->linkStations[link.bin];
            if (!loss && receiver != nullptr) ++counts->linkReceptions[link.bin];
        }
        if (receiver == nullptr) continue;  // left the simulation during the frame
        if (loss) {
            if (trace() != nullptr && link.distance <= settings_.traceRange) traceLost(*tx, r, link.distance, *loss);
            continue;
        }
        ++receptions_;
        kernel::SimTime extra;
        if (settings_.extraDelay != ChannelSettings::ExtraDelay::None) {
            auto random = CounterRandom::ofFrame(frameKey, keys_[r], DrawPurpose::Delay);
            double seconds = settings_.delay;
            if (settings_.extraDelay == ChannelSettings::ExtraDelay::Uniform) {
                seconds = settings_.delayMin + (settings_.delayMax - settings_.delayMin) * random.uniform01();
            } else if (settings_.extraDelay == ChannelSettings::ExtraDelay::Gamma) {
                seconds = random.gamma(settings_.delayShape) * settings_.delay / settings_.delayShape;
            }
            extra = kernel::SimTime::fromSeconds(seconds);
        }
        if (trace() != nullptr) {
            TraceLine line;
            line.event = TraceLine::Event::Rx;
            line.t = simTime() + extra;
            line.message = &message;
            line.station = ids_[r];
            line.sender = ids_[tx->sender];
            line.seq = message.sequence();
            line.distance = link.distance;
            line.delay = delay + extra.seconds();
            line.powerDbm = link.powerDbm;
            line.sinrDb = sinrDb;
            trace()->record(line, simTime());
        }
        if (drawnDelay) {
            deliverLater(tx->message, {receiver}, {ids_[r]}, extra);
        } else {
            receivers.push_back(receiver);
            stations.push_back(ids_[r]);
        }
    }
    flush();

    const Slot s = tx->sender;
    transmitting_[s] = 0;
    if (!sensedBusy_[s]) idleSince_[s] = simTime();  // AIFS again after its own frame
    setCbrBusy(s);
    if (!queue_[s].empty()) startAccess(s);
    // A few spares cover the frames on the air at once (airtimes are a fraction of a millisecond).
    if (spare_.size() < 64) {
        tx->message.reset();
        spare_.push_back(std::move(tx));
    }
}

void ChannelMedium::traceLost(const Transmission& tx, Slot receiver, double distance, LossReason reason) {
    TraceLine line;
    line.event = TraceLine::Event::Lost;
    line.t = simTime();
    line.message = tx.message.get();
    line.station = ids_[receiver];
    line.sender = ids_[tx.sender];
    line.seq = tx.message->sequence();
    line.distance = distance;
    line.reason = reason;
    trace()->record(line, simTime());
}

void ChannelMedium::sampleLoad() {
    const kernel::SimTime now = simTime();
    if (shadowing_) shadowing_->forget(now);
    for (Slot s = 0; s < static_cast<Slot>(ids_.size()); ++s) {
        if (cbrBusy_[s]) {
            busyNs_[s] += (now - cbrSince_[s]).raw();
            cbrSince_[s] = now;
        }
        const kernel::SimTime window = now - windowStart_[s];
        if (present_[s] && window > kernel::SimTime::zero()) {
            cbr_[s] = static_cast<double>(busyNs_[s]) / static_cast<double>(window.raw());
            dcc_[s].update(cbr_[s]);
            if (!load_) load_.emplace();
            ++load_->samples;
            cbrSum_ += cbr_[s];
            load_->meanCbr = cbrSum_ / static_cast<double>(load_->samples);
            load_->maxCbr = std::max(load_->maxCbr, cbr_[s]);
        }
        busyNs_[s] = 0;
        windowStart_[s] = now;
    }
}

std::optional<kernel::SimTime> ChannelMedium::dccInterval(const std::string& station) const {
    const auto it = slotOf_.find(station);
    if (it == slotOf_.end()) return DccStateMachine{}.transmissionInterval();
    return dcc_[it->second].transmissionInterval();
}

std::optional<double> ChannelMedium::channelBusyRatio(const std::string& station) const {
    const auto it = slotOf_.find(station);
    if (it == slotOf_.end()) return 0.0;
    return cbr_[it->second];
}

}  // namespace sbsim::radio
