#include "ServicesTestSupport.h"

#include "sbsim/services/Middleware.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/effects/SignalEffect.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::services::test {

SBSIM_REGISTER_SERVICE_AS(ProbeService, "TestProbe");
SBSIM_REGISTER_SERVICE_AS(TestProbeB, "TestProbeB");
SBSIM_REGISTER_SERVICE_AS(TestProbeC, "TestProbeC");
SBSIM_REGISTER_SERVICE_AS(TestProbeD, "TestProbeD");
SBSIM_REGISTER_SERVICE_AS(TestProbeE, "TestProbeE");
SBSIM_REGISTER_SERVICE_AS(TestProbeF, "TestProbeF");

ProbeLog* ProbeLog::current_ = nullptr;

ProbeLog::ProbeLog() {
    if (current_ != nullptr) throw std::logic_error("one ProbeLog at a time");
    current_ = this;
}

ProbeLog::~ProbeLog() { current_ = nullptr; }

ProbeLog& ProbeLog::current() {
    if (current_ == nullptr) throw std::logic_error("a ProbeService was created without a ProbeLog");
    return *current_;
}

std::vector<ProbeRecord*> ProbeLog::of(const std::string& vehicle) const {
    std::vector<ProbeRecord*> out;
    for (const auto& r : records) {
        if (r->vehicle == vehicle) out.push_back(r.get());
    }
    return out;
}

ProbeRecord* ProbeLog::find(const std::string& vehicle, const std::string& type) const {
    for (const auto& r : records) {
        if (r->vehicle == vehicle && r->type == type) return r.get();
    }
    return nullptr;
}

ProbeService& ProbeLog::probe(const std::string& vehicle, const std::string& type) const {
    ProbeRecord* r = find(vehicle, type);
    if (r == nullptr || r->live == nullptr) {
        ADD_FAILURE() << "no live " << type << " on " << vehicle;
        throw std::logic_error("no live " + type + " on " + vehicle);
    }
    return *r->live;
}

ProbeService::ProbeService() : log_(ProbeLog::current()) {
    auto record = std::make_unique<ProbeRecord>();
    record_ = record.get();
    record_->live = this;
    log_.records.push_back(std::move(record));
}

ProbeService::~ProbeService() { record_->live = nullptr; }

void ProbeService::called() {
    if (finished_) ++record_->callsAfterFinish;
}

void ProbeService::initialize() {
    called();
    ++record_->initializeCalls;
    record_->initializedAt = simTime();
    record_->name = name();
    record_->vehicle = vehicleId();
    record_->type = name().substr(std::min(name().size(), vehicleId().size() + 1));
    record_->controllerId = vehicle().id();
    record_->selfIndexAtInit = selfIndex();
    if (numberParameter("askSumo", 0) != 0) record_->liveType = vehicle().typeId();
    if (numberParameter("listenAll", 0) != 0) listenToAllSignals();
    beacon_ = numberParameter("beacon", 0) != 0;
    tick_ = SimTime::fromSeconds(numberParameter("tick", 0));
    if (tick_ > SimTime::zero()) scheduleAfter(tick_, tickTimer_);
    const double far = numberParameter("farTimer", 0);
    if (far > 0) {
        record_->farTimer = std::make_unique<kernel::Message>("probe far timer");
        scheduleAt(SimTime::fromSeconds(far), *record_->farTimer);
    }
}

void ProbeService::trigger() {
    called();
    record_->triggers.push_back(simTime());
    log_.triggerOrder.emplace_back(simTime(), vehicleId());
    if (!beacon_) return;
    Sent sent{simTime(), nextSeq_++, {}};
    if (log_.beaconRange > 0) {
        const auto self = selfIndex();
        const auto& snap = snapshot();
        if (self) {
            for (VehicleSnapshot::Index j = 0; j < snap.size(); ++j) {
                if (j == *self) continue;
                const double d = (snap.positions().col(j) - snap.positions().col(*self)).norm();
                if (d <= log_.beaconRange) sent.inRange.push_back(snap.ids()[j]);
            }
        }
    }
    const int seq = sent.seq;
    record_->sent.push_back(std::move(sent));
    send(std::make_unique<TestMessage>("Beacon", seq));
}

void ProbeService::handleMessage(kernel::Message& msg) {
    called();
    if (&msg == &tickTimer_) {
        record_->ticks.push_back(simTime());
        scheduleAfter(tick_, tickTimer_);
    } else if (record_->farTimer && &msg == record_->farTimer.get()) {
        ++record_->farFired;
    } else {
        Service::handleMessage(msg);
    }
}

void ProbeService::receiveSignal(const traffic::StoryboardSignal& signal) {
    called();
    record_->signals.emplace_back(simTime(), signal);
}

void ProbeService::indicate(const radio::V2xMessage& message) {
    called();
    const auto& m = dynamic_cast<const TestMessage&>(message);
    record_->indications.push_back(
        {simTime(), std::string(m.typeName()), m.sender(), m.sentAt(), m.seq(), m.sequence()});
}

void ProbeService::finish() {
    called();
    finished_ = true;
    record_->finishes.push_back(simTime());
    record_->finishedBySimulationFinish = log_.simulationFinishing;
}

void FakeSumo::depart(const std::string& id) { emit(traffic::SumoBridge::departedSignal, std::string_view(id)); }
void FakeSumo::arrive(const std::string& id) { emit(traffic::SumoBridge::arrivedSignal, std::string_view(id)); }
void FakeSumo::stepDone(const VehicleSnapshot& snapshot) {
    emit(traffic::SumoBridge::stepSignal, static_cast<const kernel::Object&>(snapshot));
}

namespace {
struct Action : kernel::Message {
    Action() : kernel::Message("script action") {}
    std::function<void()> run;
};
}  // namespace

void Script::at(SimTime t, std::function<void()> action, int priority) {
    auto msg = std::make_unique<Action>();
    msg->setPriority(priority);
    msg->run = std::move(action);
    simulation().schedule(std::move(msg), t, *this);
}

void Script::handleMessage(kernel::Message& msg) { static_cast<Action&>(msg).run(); }

Harness::Harness(std::string_view servicesXml, radio::DiscSettings disc, SimTime interval, std::uint64_t seed)
    : Harness(ServicesConfig::parse(servicesXml, "test.xml"), disc, interval, seed) {}

Harness::Harness(ServicesConfig config, radio::DiscSettings disc, SimTime interval, std::uint64_t seed)
    : sim(seed),
      sumo(sim.emplaceModule<FakeSumo>()),
      manager(sim.emplaceModule<ServiceManager>(std::move(config), interval, snapshot, registry)),
      medium(sim.emplaceModule<radio::DiscMedium>(disc, snapshot,
                                                  [this](const std::string& id) { return manager.middlewareOf(id); })),
      script(sim.emplaceModule<Script>()) {
    manager.setMedium(medium);
    manager.attach(sumo);
}

void Harness::step(SimTime t, std::vector<VehicleSnapshot::Vehicle> vehicles) {
    script.at(
        t,
        [this, t, vehicles = std::move(vehicles)]() mutable {
            const std::vector<std::string> before = snapshot.ids();
            snapshot.assign(std::move(vehicles), t);
            const std::vector<std::string>& after = snapshot.ids();
            std::vector<std::string> departed;
            std::vector<std::string> arrived;
            std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(departed));
            std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(arrived));
            for (const auto& id : departed) sumo.depart(id);
            for (const auto& id : arrived) sumo.arrive(id);
            sumo.stepDone(snapshot);
        },
        traffic::SumoBridge::kStepPriority);
}

VehicleSnapshot::Vehicle vehicle(std::string id, double x, double y, std::string type) {
    VehicleSnapshot::Vehicle v;
    v.id = std::move(id);
    v.x = x;
    v.y = y;
    v.type = std::move(type);
    return v;
}

storyboard::StoryPtr signalStory(const std::string& name, const std::string& ego, double begin,
                                 const std::string& cause) {
    using namespace storyboard;
    return std::make_shared<Story>(
        std::make_shared<AndCondition>(std::make_shared<CarSetCondition>(std::set<std::string>{ego}),
                                       std::make_shared<TimeCondition>(secs(begin))),
        std::vector<EffectPtr>{std::make_shared<SignalEffect>(cause)}, name);
}

std::vector<std::string> signalsOf(const ProbeRecord* r) {
    std::vector<std::string> out;
    if (r == nullptr) return {"no such record"};
    for (const auto& [t, s] : r->signals) out.push_back(t.str() + " " + s.story + " " + s.ego + " " + s.cause);
    return out;
}

std::vector<SimTime> every(SimTime first, SimTime step, SimTime last) {
    std::vector<SimTime> out;
    for (SimTime t = first; t <= last; t += step) out.push_back(t);
    return out;
}

SimTime triggerFrom(const Harness& h, const std::string& id, SimTime t) {
    SimTime at = Middleware::clockPhase(h.sim.seed(), id, secs(0.1));
    while (at < t) at += secs(0.1);
    return at;
}

}  // namespace sbsim::services::test
