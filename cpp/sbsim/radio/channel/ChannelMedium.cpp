#include "sbsim/radio/channel/ChannelMedium.h"

#include <algorithm>
#include <stdexcept>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Receiver.h"

namespace sbsim::radio {

namespace {
enum TimerKind { kAccess = ChannelAccess::kTimerKind, kEnd = 2, kLoad = 3 };
}  // namespace

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
    std::shared_ptr<const StepLinks> step;   // every link, shared with the sender's step
    std::vector<Link> links;                 // the drawn ones, in the step's order
    std::vector<std::uint32_t> halfAtStart;  // traced only: interference-only links whose receiver sent
    EndTimer end;
};

ChannelMedium::ChannelMedium(ChannelSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory,
                             std::shared_ptr<const Obstacles> obstacles)
    : Medium(std::move(directory)),
      settings_(std::move(settings)),
      snapshot_(snapshot),
      reception_((settings_.validate(), settings_), *this),
      budget_(settings_, std::move(obstacles), stations_, snapshot_, fixedStations()),
      access_(settings_, *this) {
    setSecured(settings_.secured);
}

ChannelMedium::~ChannelMedium() = default;

void ChannelMedium::initialize() {
    seed_ = simulation().seed();
    access_.setSeed(seed_);
    budget_.start(seed_);
    loadTimer_ = std::make_unique<kernel::Message>("channel load", kLoad);
    scheduleAt(DccStateMachine::kSampling * (simTime() / DccStateMachine::kSampling + 1), *loadTimer_);
}

void ChannelMedium::handleMessage(kernel::Message& msg) {
    switch (msg.kind()) {
        case kAccess:
            return startTransmission(static_cast<ChannelAccess::Timer&>(msg).station);
        case kEnd:
            return endTransmission(static_cast<EndTimer&>(msg).tx);
        case kLoad:
            load_.sample(simTime(), stations_.present, dccChanged_);
            if (trace() != nullptr) {
                for (const Slot s : dccChanged_) {
                    const DccStateMachine& dcc = load_.dcc(s);
                    trace()->dccChanged(
                        {simTime(), stations_.ids[s], dcc.name(), load_.busyRatio(s), dcc.transmissionInterval()});
                }
            }
            budget_.forget(simTime());
            return scheduleAfter(DccStateMachine::kSampling, msg);
        default:
            return Medium::handleMessage(msg);
    }
}

ChannelMedium::Slot ChannelMedium::stationOf(const std::string& id) {
    if (const auto it = stations_.slotOf.find(id); it != stations_.slotOf.end()) return it->second;
    const Slot s = stations_.add(id, stationIndex(id));
    reception_.addStation();
    load_.addStation(simTime());
    access_.addStation(stations_.keys[s]);
    budget_.addStation();
    return s;
}

void ChannelMedium::refreshStations() {
    if (stations_.refreshedAt == snapshot_.time() &&
        stations_.slotOfIndex.size() == static_cast<std::size_t>(snapshot_.size()))
        return;
    stations_.refreshedAt = snapshot_.time();
    std::fill(stations_.present.begin(), stations_.present.end(), 0);
    std::fill(stations_.receiver.begin(), stations_.receiver.end(), nullptr);
    stations_.slotOfIndex.assign(static_cast<std::size_t>(snapshot_.size()), -1);
    const auto& positions = snapshot_.positions();
    for (traffic::VehicleSnapshot::Index i = 0; i < snapshot_.size(); ++i) {
        const std::string& id = snapshot_.ids()[i];
        Slot s = -1;
        if (const auto it = stations_.slotOf.find(id); it != stations_.slotOf.end()) {
            s = it->second;
        } else if (receiverOf(id) != nullptr) {
            s = stationOf(id);
        } else {
            continue;  // a vehicle without services is no station
        }
        stations_.slotOfIndex[i] = s;
        stations_.present[s] = 1;
        // Looked up once a step, not once a link: modules come and go only with SUMO's steps.
        stations_.receiver[s] = receivingSide(id);
        stations_.x[s] = positions(0, i);
        stations_.y[s] = positions(1, i);
    }
    // Stationary stations stay where they are; they are stations once their module exists.
    const FixedStations& fixed = fixedStations();
    for (FixedStations::Index k = 0; k < fixed.size(); ++k) {
        const std::string& id = fixed.ids()[k];
        if (stations_.slotOf.count(id) == 0 && receiverOf(id) == nullptr) continue;
        const Slot s = stationOf(id);
        stations_.present[s] = 1;
        stations_.receiver[s] = receivingSide(id);
        stations_.x[s] = fixed.positions()(0, k);
        stations_.y[s] = fixed.positions()(1, k);
    }
    budget_.newStep();
    if (const FarCells* cells = budget_.farCells()) reception_.moveStations(*cells);
}

void ChannelMedium::broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message) {
    if (!message) throw std::invalid_argument("cannot send a null V2X message");
    stamp(*message, sender);
    refreshStations();
    const auto index = snapshot_.indexOf(sender);
    const auto fixed = index ? std::nullopt : fixedStations().indexOf(sender);
    if (!index && !fixed) return;  // not on the road (yet): nobody hears it
    const Slot s = stationOf(sender);
    if (!stations_.present[s]) {
        stations_.present[s] = 1;  // a station whose directory entry appeared after the last refresh
        const Eigen::Vector2d at =
            index ? Eigen::Vector2d(snapshot_.positions().col(*index)) : fixedStations().positions().col(*fixed);
        stations_.x[s] = at.x();
        stations_.y[s] = at.y();
    }
    std::shared_ptr<const V2xMessage> shared(std::move(message));
    if (!access_.enqueue(s, shared)) {
        if (trace() != nullptr) {
            TraceLine line;
            line.event = TraceLine::Event::Lost;
            line.t = simTime();
            line.message = shared.get();
            line.station = stations_.ids[s];
            line.sender = stations_.ids[s];
            line.seq = shared->sequence();
            line.reason = LossReason::Queue;
            trace()->record(line, simTime());
        }
        return;
    }
    if (!access_.contending(s) && !reception_.sending(s) && access_.queued(s) == 1) {
        access_.start(s, reception_.sensesBusy(s));
    }
}

void ChannelMedium::channelSensed(Slot s, bool busy) {
    if (busy) {
        access_.channelBusy(s);
    } else {
        access_.channelIdle(s);
    }
    setCbrBusy(s);
}

void ChannelMedium::setCbrBusy(Slot s) {
    // The channel counts busy for the busy ratio while sensed busy or while the station sends.
    load_.setBusy(s, reception_.sensesBusy(s) || reception_.sending(s), simTime());
}

void ChannelMedium::startTransmission(Slot s) {
    refreshStations();
    std::unique_ptr<Transmission> tx;
    if (spare_.empty()) {
        tx = std::make_unique<Transmission>(nextTx_);
    } else {
        tx = std::move(spare_.back());
        spare_.pop_back();
        tx->id = nextTx_;
        tx->end.tx = nextTx_;
        tx->links.clear();
        tx->halfAtStart.clear();
    }
    ++nextTx_;
    tx->sender = s;
    tx->message = access_.take(s);
    tx->start = simTime();
    ++transmissions_;
    if (trace() != nullptr) {
        TraceLine line;
        line.event = TraceLine::Event::Tx;
        line.t = simTime();
        line.message = tx->message.get();
        line.station = stations_.ids[s];
        line.seq = tx->message->sequence();
        line.x = stations_.x[s];
        line.y = stations_.y[s];
        line.cbr = load_.busyRatio(s);
        trace()->record(line, simTime());
    }
    if (stations_.present[s]) {
        const std::uint64_t frameKey = CounterRandom::frameKey(seed_, stations_.keys[s], tx->message->sequence());
        tx->step = budget_.computeLinks(s, frameKey, simTime(), tx->links, simulation().parallel());
    } else {
        static const auto nobody = std::make_shared<const StepLinks>();
        tx->step = nobody;
    }

    // The sender stops receiving: whatever it was receiving is lost to half-duplex.
    reception_.startSending(s, tx->id, simTime());
    setCbrBusy(s);
    reception_.frameStarts(tx->id, *tx->step, tx->links, trace() != nullptr ? &tx->halfAtStart : nullptr);
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
    refreshStations();  // the receivers' modules as of the last step
    Counts* counts = countsOf(message);
    const std::uint64_t frameKey = CounterRandom::frameKey(seed_, stations_.keys[tx->sender], message.sequence());
    // Receptions without a drawn delay share one kernel event (in receiver order, as their own
    // events would have run); a drawn delay gives each its own.
    const bool drawnDelay = settings_.extraDelay == ChannelSettings::ExtraDelay::Uniform ||
                            settings_.extraDelay == ChannelSettings::ExtraDelay::Gamma;
    Receivers receivers;
    std::vector<StationIndex> stations;
    const kernel::SimTime sharedDelay = settings_.extraDelay == ChannelSettings::ExtraDelay::Constant
                                            ? kernel::SimTime::fromSeconds(settings_.delay)
                                            : kernel::SimTime::zero();
    const auto flush = [&] {
        deliverLater(tx->message, std::move(receivers), std::move(stations), sharedDelay);
        receivers.clear();
        stations.clear();
    };

    const StepLinks& step = *tx->step;
    // The far tier's cells: their fields fall, their receivers counted by the centre's distance.
    reception_.farEnds(step);
    if (counts != nullptr) {
        for (std::size_t k = 0; k < step.farCell.size(); ++k) {
            const std::size_t bin = step.farBin[k];
            if (counts->linkStations.size() <= bin) {
                counts->linkStations.resize(bin + 1);
                counts->linkReceptions.resize(bin + 1);
            }
            counts->linkStations[bin] += step.farOccupants[k];
        }
    }
    std::size_t drawn = 0;
    for (std::size_t k = 0; k < step.size(); ++k) {
        if (step.tier[k] != StepLinks::kDrawn) {
            // Interference only: it leaves the power its receiver hears, and is lost below the
            // sensing threshold (or to half-duplex).
            const Slot r = step.receivers[k];
            const bool counted = step.tier[k] == StepLinks::kInterference;
            if (counted) {
                const double total = reception_.leave(r, step.units[k]);
                if (access_.contending(r) && reception_.changesSense(r, total)) flush();
                reception_.setSensedPower(r, total);
            }
            if (counts != nullptr) counts->countLink(step.bin[k], false);
            if (trace() != nullptr && stations_.receiver[r] != nullptr && step.distance[k] <= settings_.traceRange) {
                const bool half = (counted && reception_.sentSince(r, tx->start)) ||
                                  std::find(tx->halfAtStart.begin(), tx->halfAtStart.end(), k) != tx->halfAtStart.end();
                traceLost(*tx, r, step.distance[k], half ? LossReason::HalfDuplex : LossReason::Sensing);
            }
            continue;
        }
        Link& link = tx->links[drawn++];
        const Slot r = link.receiver;
        const double total = reception_.frameEnds(id, tx->start, link);
        if (link.counted) {
            // A station that senses the channel free may schedule its backoff's end, possibly at
            // a delivery's time: the receptions so far go first, as their own events did.
            if (access_.contending(r) && reception_.changesSense(r, total)) flush();
            reception_.setSensedPower(r, total);
        }

        double sinrDb = 0;
        const std::optional<LossReason> loss = reception_.decode(link, frameKey, stations_.keys[r], sinrDb);
        Receiver* receiver = stations_.receiver[r];
        if (counts != nullptr) counts->countLink(link.bin, !loss && receiver != nullptr);  // the bin computed per step
        if (receiver == nullptr) continue;  // left the simulation during the frame
        if (loss) {
            if (trace() != nullptr && link.distance <= settings_.traceRange) traceLost(*tx, r, link.distance, *loss);
            continue;
        }
        ++receptions_;
        kernel::SimTime extra;
        if (settings_.extraDelay != ChannelSettings::ExtraDelay::None) {
            auto random = CounterRandom::ofFrame(frameKey, stations_.keys[r], DrawPurpose::Delay);
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
            line.station = stations_.ids[r];
            line.sender = stations_.ids[tx->sender];
            line.seq = message.sequence();
            line.distance = link.distance;
            line.delay = delay + extra.seconds();
            line.powerDbm = link.powerDbm;
            line.sinrDb = sinrDb;
            trace()->record(line, simTime());
        }
        if (drawnDelay) {
            deliverLater(tx->message, {receiver}, {stations_.index[r]}, extra);
        } else {
            receivers.push_back(receiver);
            stations.push_back(stations_.index[r]);
        }
    }
    flush();

    const Slot s = tx->sender;
    reception_.stopSending(s);
    setCbrBusy(s);
    access_.frameEnded(s, reception_.sensesBusy(s));
    // A few spares cover the frames on the air at once (airtimes are a fraction of a millisecond).
    if (spare_.size() < 64) {
        tx->message.reset();
        tx->step.reset();  // the sender's next step may then reuse its links in place
        spare_.push_back(std::move(tx));
    }
}

void ChannelMedium::traceLost(const Transmission& tx, Slot receiver, double distance, LossReason reason) {
    TraceLine line;
    line.event = TraceLine::Event::Lost;
    line.t = simTime();
    line.message = tx.message.get();
    line.station = stations_.ids[receiver];
    line.sender = stations_.ids[tx.sender];
    line.seq = tx.message->sequence();
    line.distance = distance;
    line.reason = reason;
    trace()->record(line, simTime());
}

std::optional<kernel::SimTime> ChannelMedium::dccInterval(const std::string& station) const {
    const auto it = stations_.slotOf.find(station);
    if (it == stations_.slotOf.end()) return DccStateMachine{}.transmissionInterval();
    return load_.dcc(it->second).transmissionInterval();
}

std::optional<double> ChannelMedium::channelBusyRatio(const std::string& station) const {
    const auto it = stations_.slotOf.find(station);
    if (it == stations_.slotOf.end()) return 0.0;
    return load_.busyRatio(it->second);
}

}  // namespace sbsim::radio
