#pragma once
// Shared by the service tests: a probe service that records every call it gets (registered as
// "TestProbe", "TestProbeB", ... in ServicesTestSupport.cpp), a V2X test message, and for the
// hand-driven tests a stand-in for the SUMO bridge plus a module that runs actions at given times.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Message.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/V2xMessage.h"
#include "sbsim/radio/disc/DiscMedium.h"
#include "sbsim/services/Service.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/traffic/StoryboardSignal.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::services::test {

using kernel::SimTime;
using traffic::VehicleSnapshot;

inline SimTime secs(double s) { return SimTime::fromSeconds(s); }

class TestMessage : public radio::V2xMessage {
public:
    TestMessage(std::string type, int seq) : type_(std::move(type)), seq_(seq) {}
    std::string_view typeName() const override { return type_; }
    std::size_t byteSize() const override { return 100; }
    int seq() const { return seq_; }

private:
    std::string type_;
    int seq_;
};

struct Indication {
    SimTime at;
    std::string type;
    std::string sender;
    SimTime sentAt;
    int seq;
    std::uint64_t sequence;  ///< the medium's number of the sender's frame
};

/// A beacon a probe sent from trigger(), with the vehicles a brute-force search found in range.
struct Sent {
    SimTime at;
    int seq;
    std::vector<std::string> inRange;  ///< ascending
};

class ProbeService;

/// Everything one probe instance saw. Records outlive their service.
struct ProbeRecord {
    std::string name;     ///< module name at initialize(): "<vehicle>.<type>"
    std::string type;     ///< the service type from the services file
    std::string vehicle;  ///< vehicleId() in initialize()
    std::string controllerId;
    std::optional<VehicleSnapshot::Index> selfIndexAtInit;
    std::string liveType;  ///< vehicle().typeId() in initialize(), with askSumo="1"
    int initializeCalls = 0;
    SimTime initializedAt;
    std::vector<SimTime> triggers;
    std::vector<SimTime> ticks;  ///< the service's own periodic timer (tick="<s>")
    int farFired = 0;
    /// A self-message owned here, not by the service (farTimer="<s>", absolute time), so the test
    /// can see whether the kernel still holds it after the service is gone.
    std::unique_ptr<kernel::Message> farTimer;
    std::vector<SimTime> finishes;
    bool finishedBySimulationFinish = false;
    int callsAfterFinish = 0;
    std::vector<std::pair<SimTime, traffic::StoryboardSignal>> signals;
    std::vector<Indication> indications;
    std::vector<Sent> sent;
    ProbeService* live = nullptr;  ///< the service while it exists
};

/// Collects the records of the probes created while it exists (one at a time).
class ProbeLog {
public:
    ProbeLog();
    ~ProbeLog();
    ProbeLog(const ProbeLog&) = delete;
    ProbeLog& operator=(const ProbeLog&) = delete;

    static ProbeLog& current();

    std::vector<std::unique_ptr<ProbeRecord>> records;
    /// Every trigger() of every probe, in call order.
    std::vector<std::pair<SimTime, std::string>> triggerOrder;
    /// Set by the test just before Simulation::finish().
    bool simulationFinishing = false;
    /// Probes with beacon="1" list the vehicles within this distance when they send.
    double beaconRange = 0;

    /// The records of `vehicle`, in creation order.
    std::vector<ProbeRecord*> of(const std::string& vehicle) const;
    /// The record of `type` on `vehicle`, or nullptr.
    ProbeRecord* find(const std::string& vehicle, const std::string& type = "TestProbe") const;
    /// The live probe of `type` on `vehicle`; fails the test (throws) if there is none.
    ProbeService& probe(const std::string& vehicle, const std::string& type = "TestProbe") const;

private:
    static ProbeLog* current_;
};

/// Records every call. Parameters (attributes in the services file): listenAll="1", tick="<s>"
/// (own periodic timer), farTimer="<s>" (a timer at that absolute time), beacon="1" (sends a
/// "Beacon" on every trigger), askSumo="1" (asks SUMO for the type in initialize()).
class ProbeService : public Service {
public:
    ProbeService();
    ~ProbeService() override;

    ProbeRecord& record() const { return *record_; }
    /// Service::send, from outside.
    void sendNow(std::unique_ptr<radio::V2xMessage> message) { send(std::move(message)); }

    void initialize() override;
    void trigger() override;
    void handleMessage(kernel::Message& msg) override;
    void receiveSignal(const traffic::StoryboardSignal& signal) override;
    void indicate(const radio::V2xMessage& message) override;
    void finish() override;

private:
    void called();

    ProbeLog& log_;
    ProbeRecord* record_;
    bool finished_ = false;
    bool beacon_ = false;
    int nextSeq_ = 0;
    SimTime tick_;
    kernel::Message tickTimer_{"probe tick"};
};

// The same probe under several type names (each registration needs its own identifier).
using TestProbeB = ProbeService;
using TestProbeC = ProbeService;
using TestProbeD = ProbeService;
using TestProbeE = ProbeService;
using TestProbeF = ProbeService;

/// Stands in for traffic::SumoBridge: emits its departed / arrived / step signals on demand.
class FakeSumo : public kernel::Module {
public:
    FakeSumo() : kernel::Module("sumo") {}
    void depart(const std::string& id);
    void arrive(const std::string& id);
    void stepDone(const VehicleSnapshot& snapshot);
};

/// Runs actions at given times, as events.
class Script : public kernel::Module {
public:
    Script() : kernel::Module("script") {}
    /// Among events due at `t`, a smaller priority runs first (SumoBridge::kStepPriority: as a step).
    void at(SimTime t, std::function<void()> action, int priority = 0);
    void handleMessage(kernel::Message& msg) override;
};

/// A simulation with a fake SUMO, a hand-made snapshot, a service manager and a medium, wired as
/// in app/run/Scenario.cpp. step() plays the part of a SUMO step.
class Harness {
public:
    /// `seed`: the simulation's, which seeds the medium's packet losses.
    explicit Harness(std::string_view servicesXml, radio::DiscSettings disc = {}, SimTime interval = secs(0.1),
                     std::uint64_t seed = 0);
    /// The same with a configuration already loaded (a file with its use-case file beside it).
    explicit Harness(ServicesConfig config, radio::DiscSettings disc = {}, SimTime interval = secs(0.1),
                     std::uint64_t seed = 0);

    /// At `t`, as a SUMO step would (before other events due then): the snapshot becomes
    /// `vehicles`; vehicles new to it depart, vehicles missing from it arrive (each in ascending
    /// id order), then the step signal goes out.
    void step(SimTime t, std::vector<VehicleSnapshot::Vehicle> vehicles);
    /// Runs `action` at `t`, after the step due then.
    void at(SimTime t, std::function<void()> action) { script.at(t, std::move(action)); }

    ProbeLog log;  // first: the services write into it until they are destroyed
    VehicleSnapshot snapshot;
    traffic::VehicleRegistry registry;  // the services' and the board's, as in a run
    kernel::Simulation sim;
    FakeSumo& sumo;
    ServiceManager& manager;
    radio::DiscMedium& medium;
    Script& script;
};

VehicleSnapshot::Vehicle vehicle(std::string id, double x = 0, double y = 0, std::string type = "car");

/// A story for `ego` from `begin` on, with a SignalEffect of `cause`.
storyboard::StoryPtr signalStory(const std::string& name, const std::string& ego, double begin,
                                 const std::string& cause);

/// (time, story, ego, cause) of every signal a record got.
std::vector<std::string> signalsOf(const ProbeRecord* r);

/// `first`, then every `step`, while <= `last`.
std::vector<SimTime> every(SimTime first, SimTime step, SimTime last);
/// Station `id`'s first trigger at or after `t` on its own clock, for a station present from 0 s
/// with the harness's 0.1 s interval (Middleware::clockPhase).
SimTime triggerFrom(const Harness& h, const std::string& id, SimTime t);

}  // namespace sbsim::services::test
