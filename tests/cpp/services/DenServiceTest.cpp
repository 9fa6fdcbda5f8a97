// The DEN service on hand-made steps: TractionLoss on the storyboard's signal sends its DENM with
// Artery's constants, repeated every second, blocked for 20 s; receivers inside the destination
// circle (and in radio range) keep it once in their memory, those outside it never see it; a
// StoryboardEvent ends its event on the end signal: the repetition stops, receivers drop it. CAMs
// fill the receivers' local dynamic maps.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "ServicesTestSupport.h"
#include "sbsim/facilities/Cam.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ca/CaService.h"
#include "sbsim/services/den/DenService.h"
#include "sbsim/services/den/TractionLoss.h"

namespace sbsim::services::test {
namespace {

/// Records what every service with the probe's hooks saw of CAMs and DENMs.
struct ItsLog {
    std::map<std::string, std::vector<facilities::DenmContent>> denms;  // per receiver
    std::map<std::string, std::size_t> cams;
};
ItsLog* itsLog = nullptr;

class ItsProbe : public Service, public facilities::ItsMessageHandler {
public:
    void indicateCam(const facilities::Cam&) override { ++itsLog->cams[vehicleId()]; }
    void indicateDenm(const facilities::Denm& d) override { itsLog->denms[vehicleId()].push_back(d.content()); }
};
SBSIM_REGISTER_SERVICE(ItsProbe);

/// Sends storyboard signals as the board does.
struct SignalSource : kernel::Module {
    SignalSource() : kernel::Module("story") {}
    void send(const traffic::StoryboardSignal& s) {
        emit(traffic::StoryboardSignal::id, static_cast<const kernel::Object&>(s));
    }
};

struct PhaseLog : facilities::DenmPhaseSink {
    std::vector<facilities::DenmPhaseEvent> events;
    void denmPhase(const facilities::DenmPhaseEvent& e) override { events.push_back(e); }
    std::vector<std::string> of(const std::string& station) const {
        std::vector<std::string> out;
        for (const auto& e : events) {
            if (e.station == station)
                out.push_back(std::string(facilities::phaseName(e.phase)) + "@" + e.time.str() + " " + e.action.str());
        }
        return out;
    }
};

/// Writes `files` (name → text) into a fresh folder and loads its services.xml.
ServicesConfig loadFiles(const std::map<std::string, std::string>& files) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("sbsim-den-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (const auto& [name, text] : files) std::ofstream(dir / name) << text;
    return ServicesConfig::load(dir / "services.xml");
}

constexpr std::string_view kServices = R"(<services>
    <service type="artery.application.DenService"><listener port="2002"/></service>
    <service type="ItsProbe"/>
</services>)";

class DenTest : public ::testing::Test {
protected:
    void SetUp() override { itsLog = &its; }
    void TearDown() override { itsLog = nullptr; }

    void signal(Harness& h, double t, const std::string& ego, const std::string& cause, bool onExit = false) {
        auto& source = h.sim.emplaceModule<SignalSource>();
        h.at(secs(t), [&source, ego, cause, onExit] {
            traffic::StoryboardSignal s;
            s.cause = cause;
            s.ego = ego;
            s.story = "test";
            s.onExit = onExit;
            source.send(s);
        });
    }
    DenService& den(Harness& h, const std::string& vehicle) {
        for (Service* s : h.manager.middlewareOf(vehicle)->services()) {
            if (auto* d = dynamic_cast<DenService*>(s)) return *d;
        }
        throw std::logic_error("no DenService on " + vehicle);
    }

    ItsLog its;
    PhaseLog phases;
};

TEST_F(DenTest, TractionLossRepeatsEverySecondToTheStationsInsideItsArea) {
    radio::DiscSettings disc;
    disc.range = 1500;  // the radio reaches beyond the 1,000 m destination circle
    Harness h(loadFiles({{"services.xml", std::string(kServices)},
                         {"den-use-cases.xml",
                          R"(<usecases><usecase type="artery.application.den.TractionLoss"/></usecases>)"}}),
              disc);
    h.manager.stations().setPhaseSink(&phases);
    h.step(secs(0),
           {vehicle("slippery", 0, 0), vehicle("near", 800, 0), vehicle("edge", 0, 1000), vehicle("outside", 1200, 0)});
    signal(h, 2.05, "slippery", "traction loss");
    signal(h, 5.05, "slippery", "traction loss");  // within the 20 s blocking: waits
    h.sim.run(secs(12.05));

    DenService& sender = den(h, "slippery");
    ASSERT_EQ(sender.useCases().size(), 1u);
    // Sent at the first trigger after the signal (the station's own clock), then every second to 12.05 s.
    const SimTime sent = triggerFrom(h, "slippery", secs(2.05));
    const std::size_t sends = every(sent, secs(1), secs(12.05)).size();
    EXPECT_EQ(sends, 10u);
    EXPECT_EQ(sender.denmsSent(), sends);
    ASSERT_EQ(its.denms["near"].size(), sends);
    EXPECT_EQ(its.denms["edge"].size(), sends);
    EXPECT_EQ(its.denms.count("outside"), 0u) << "outside the destination circle";
    const facilities::DenmContent& d = its.denms["near"].front();
    EXPECT_EQ(d.cause, TractionLoss::kCause);
    EXPECT_EQ(d.subcause, 0);
    EXPECT_EQ(d.relevanceDistance, 100.0);
    EXPECT_EQ(d.validity, secs(600));
    EXPECT_EQ(d.destination.radius, 1000.0);
    EXPECT_EQ(d.trafficClass, 1);
    EXPECT_EQ(d.action.str(), "slippery:1");
    EXPECT_EQ(d.detectionTime, sent);
    for (const auto& r : its.denms["near"]) EXPECT_EQ(r.referenceTime, d.referenceTime) << "repetitions are the same";
    // One event in each receiver's memory, none outside.
    EXPECT_EQ(h.manager.stations().find("near")->denms.size(), 1u);
    EXPECT_EQ(h.manager.stations().find("outside")->denms.size(), 0u);
    const SimTime ms = SimTime::fromMilliseconds(1);
    EXPECT_EQ(phases.of("slippery"), std::vector<std::string>{"new@" + sent.str() + " slippery:1"});
    EXPECT_EQ(phases.of("near"), std::vector<std::string>{"new@" + (sent + ms).str() + " slippery:1"});
    EXPECT_TRUE(phases.of("outside").empty());
}

TEST_F(DenTest, TractionLossIsBlockedFor20Seconds) {
    Harness h(loadFiles({{"services.xml", std::string(kServices)},
                         {"den-use-cases.xml", R"(<usecases><usecase type="TractionLoss"/></usecases>)"}}));
    h.manager.stations().setPhaseSink(&phases);
    h.step(secs(0), {vehicle("a", 0, 0), vehicle("b", 100, 0)});
    signal(h, 1.05, "a", "traction loss");
    signal(h, 5.05, "a", "traction loss");  // blocked for 20 s after the first: sent at the trigger after
    h.sim.run(secs(22.3));
    const SimTime first = triggerFrom(h, "a", secs(1.05));
    EXPECT_EQ(phases.of("a"),
              (std::vector<std::string>{"new@" + first.str() + " a:1", "new@" + (first + secs(20.1)).str() + " a:2"}));
}

TEST_F(DenTest, StoryboardEventEndsItsEventOnTheEndSignal) {
    Harness h(loadFiles({{"services.xml", std::string(kServices)}, {"den-use-cases.xml", R"(<usecases>
                              <usecase type="StoryboardEvent" signal="accident" endSignal="cleared" cause="2"
                                       subcause="1" relevance="500" validity="120" area="800" interval="0.5"
                                       duration="60"/>
                            </usecases>)"}}));
    h.manager.stations().setPhaseSink(&phases);
    h.step(secs(0), {vehicle("crash", 0, 0), vehicle("b", 300, 0)});
    signal(h, 1.05, "crash", "accident");
    signal(h, 4.05, "crash", "cleared", true);
    h.sim.run(secs(10));
    // From the first trigger after the signal every 0.5 s, then at 4.05 the cancellation, then nothing.
    const SimTime sent = triggerFrom(h, "crash", secs(1.05));
    const std::size_t sends = every(sent, secs(0.5), secs(4.05)).size() + 1;
    EXPECT_EQ(den(h, "crash").denmsSent(), sends);
    const auto& got = its.denms["b"];
    ASSERT_EQ(got.size(), sends);
    EXPECT_EQ(got.front().cause, 2);
    EXPECT_EQ(got.front().subcause, 1);
    EXPECT_EQ(got.front().destination.radius, 800.0);
    EXPECT_EQ(got.front().validity, secs(120));
    EXPECT_EQ(got.back().termination, facilities::Termination::Cancellation);
    EXPECT_EQ(got.back().referenceTime, secs(4.05));
    EXPECT_EQ(h.manager.stations().find("b")->denms.size(), 0u) << "the receiver dropped the event";
    EXPECT_EQ(phases.of("crash"),
              (std::vector<std::string>{"new@" + sent.str() + " crash:1", "terminate@4.05 crash:1"}));
    EXPECT_EQ(phases.of("b"),
              (std::vector<std::string>{"new@" + (sent + SimTime::fromMilliseconds(1)).str() + " crash:1",
                                        "terminate@4.051 crash:1"}));
}

TEST_F(DenTest, WithoutAUseCaseListEveryUseCaseRuns) {
    Harness h(loadFiles({{"services.xml", std::string(kServices)}}));
    h.step(secs(0), {vehicle("a", 0, 0)});
    h.sim.run(secs(0.5));
    EXPECT_EQ(den(h, "a").useCases().size(), 5u);  // Artery's five; StoryboardEvent needs a file
}

TEST_F(DenTest, CamsFillTheLocalDynamicMap) {
    Harness h(ServicesConfig::parse(R"(<services><service type="CaService"/><service type="ItsProbe"/></services>)",
                                    "test.xml"));
    h.step(secs(0), {vehicle("a", 0, 0), vehicle("b", 100, 0), vehicle("far", 5000, 0)});
    h.sim.run(secs(3.05));
    // Standing still: a CAM at the first trigger, then every second; "far" is out of range.
    const std::vector<SimTime> camsOfA = every(triggerFrom(h, "a", SimTime::zero()), secs(1), secs(3.05));
    EXPECT_EQ(its.cams["b"], camsOfA.size());
    EXPECT_EQ(its.cams["a"], every(triggerFrom(h, "b", SimTime::zero()), secs(1), secs(3.05)).size());
    EXPECT_EQ(its.cams.count("far"), 0u);
    const auto* entry = h.manager.stations().find("b")->ldm.find("a");
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(entry->cam.generationTime, camsOfA.back());
    EXPECT_EQ(entry->cam.position, Eigen::Vector2d(0, 0));
    EXPECT_EQ(h.manager.stations().find("b")->ldm.size(), 1u);
    EXPECT_EQ(h.manager.stations().find("far")->ldm.size(), 0u);
}

/// A vehicle with its dynamics.
VehicleSnapshot::Vehicle moving(std::string id, double x, double speed, double acceleration = 0) {
    auto v = vehicle(std::move(id), x, 0);
    v.speed = speed;
    v.acceleration = acceleration;
    v.angle = 90;
    return v;
}

std::string useCases(const std::string& body) { return "<usecases>" + body + "</usecases>"; }

TEST_F(DenTest, EmergencyBrakeLightOnFiveHardBrakingSamplesAbove20Kmh) {
    Harness h(loadFiles({{"services.xml", std::string(kServices)},
                         {"den-use-cases.xml", useCases(R"(<usecase type="EmergencyBrakeLight"/>)")}}));
    h.manager.stations().setPhaseSink(&phases);
    // "hard" brakes at −8 m/s² from 1.0 s; "soft" at −6.9; "slow" at −8 but drives 5 m/s.
    for (int k = 0; k <= 20; ++k) {
        const double t = k / 10.0;
        const bool braking = t >= 1.0 - 1e-9;
        h.step(secs(t), {moving("hard", 0, 25, braking ? -8 : 0), moving("soft", 50, 25, braking ? -6.9 : 0),
                         moving("slow", 100, 5, braking ? -8 : 0)});
    }
    h.sim.run(secs(2.15));
    // Samples at the five triggers from the first after 1.0 s (each sees the last step's state): the
    // buffer is full at the fifth; blocked for 100 ms after each, so again 0.2, 0.4, 0.6 s later.
    const SimTime t1 = triggerFrom(h, "hard", secs(1) + SimTime::fromNanoseconds(1));
    std::vector<std::string> expected;
    for (int k = 0; k < 4; ++k)
        expected.push_back("new@" + (t1 + secs(0.4 + 0.2 * k)).str() + " hard:" + std::to_string(k + 1));
    EXPECT_EQ(phases.of("hard"), expected);
    ASSERT_EQ(phases.of("soft").size(), 4u);
    EXPECT_EQ(phases.of("soft")[0], "new@" + (t1 + secs(0.4) + SimTime::fromMilliseconds(1)).str() + " hard:1");
    EXPECT_EQ(den(h, "soft").denmsSent(), 0u);
    EXPECT_EQ(den(h, "slow").denmsSent(), 0u);
    const auto& d = its.denms["soft"].front();
    EXPECT_EQ(d.cause, 99);
    EXPECT_EQ(d.subcause, 1);
    EXPECT_EQ(d.validity, secs(2));
    EXPECT_EQ(d.relevanceDistance, 500.0);
    EXPECT_EQ(d.destination.radius, 500.0);
    EXPECT_EQ(d.trafficClass, 0);
    EXPECT_EQ(its.denms["soft"].size(), 4u) << "no repetition";
}

TEST_F(DenTest, ImpactReductionRequestGetsResponses) {
    Harness h(loadFiles({{"services.xml", std::string(kServices)},
                         {"den-use-cases.xml", useCases(R"(<usecase type="ImpactReductionContainerExchange"/>)")}}));
    h.manager.stations().setPhaseSink(&phases);
    h.step(secs(0), {vehicle("a", 0, 0), vehicle("b", 50, 0), vehicle("far", 160, 0)});
    signal(h, 1.05, "a", "irc");
    h.sim.run(secs(3));
    // The request at 1.1, repeated at 1.2 and 1.3 (0.1 s for 0.3 s).
    EXPECT_EQ(den(h, "a").denmsSent(), 3u);
    ASSERT_FALSE(its.denms["b"].empty());
    const auto& request = its.denms["b"].front();
    EXPECT_EQ(request.cause, 97);
    EXPECT_EQ(request.impactReduction, facilities::ImpactReduction::Request);
    EXPECT_EQ(request.destination.radius, 100.0);
    // b answers each copy of the request it hears (as Artery's use case does), each answer
    // repeated 3 times; "far" is outside the 100 m area and neither hears nor answers.
    EXPECT_EQ(den(h, "b").denmsSent(), 9u);
    EXPECT_EQ(den(h, "far").denmsSent(), 0u);
    EXPECT_EQ(its.denms.count("far"), 0u);
    ASSERT_FALSE(its.denms["a"].empty());
    EXPECT_EQ(its.denms["a"].front().impactReduction, facilities::ImpactReduction::Response);
}

constexpr const char* kEndOfQueueCases =
    R"(<usecase type="TrafficJamEndOfQueue"><filters><name pattern="b"/></filters></usecase>
       <usecase type="StoryboardEvent" signal="queue" cause="27" validity="60" duration="2">
           <filters><name pattern="head"/></filters></usecase>)";

// b drives 25 m/s (90 km/h) until 2 s, then slows by 4.5 m/s² to 7 m/s (25 km/h, at 6 s); "head"
// stands 300 m ahead and, in the second test, announces a queue (cause 27) at 0.6 s.

TEST_F(DenTest, EndOfQueueNeedsAQueueHeardOf) {
    Harness h(loadFiles({{"services.xml", std::string(kServices)}, {"den-use-cases.xml", useCases(kEndOfQueueCases)}}));
    h.manager.stations().setPhaseSink(&phases);
    for (int k = 0; k <= 100; ++k) {
        const double t = k / 10.0;
        h.step(secs(t), {moving("head", 300, 0), moving("b", 0, t < 2 ? 25 : std::max(7.0, 25 - 4.5 * (t - 2)))});
    }
    h.sim.run(secs(10));
    EXPECT_TRUE(phases.of("b").empty()) << "braking alone is not enough";
}

TEST_F(DenTest, EndOfQueueAfterHardBrakingToAQueueHeardOf) {
    Harness h(loadFiles({{"services.xml", std::string(kServices)}, {"den-use-cases.xml", useCases(kEndOfQueueCases)}}));
    h.manager.stations().setPhaseSink(&phases);
    for (int k = 0; k <= 100; ++k) {
        const double t = k / 10.0;
        h.step(secs(t), {moving("head", 300, 0), moving("b", 0, t < 2 ? 25 : std::max(7.0, 25 - 4.5 * (t - 2)))});
    }
    signal(h, 0.55, "head", "queue");
    h.sim.run(secs(10));
    // b is at most 30 km/h (8.33 m/s) from 5.8 s on (7.9 m/s; 8.35 at 5.7); the newest earlier
    // sample of at least 80 km/h (22.2 m/s) is at 2.6 s (22.3 m/s): −4.5 m/s², below −3.5.
    const auto b = phases.of("b");
    ASSERT_FALSE(b.empty());
    const SimTime detected = triggerFrom(h, "b", secs(5.8) + SimTime::fromNanoseconds(1));
    EXPECT_EQ(b.back(), "new@" + detected.str() + " b:1");
    const auto& sent = its.denms["head"];
    ASSERT_FALSE(sent.empty());
    EXPECT_EQ(sent.back().cause, 27);
    EXPECT_EQ(sent.back().action.station, "b");
    EXPECT_EQ(sent.back().trafficDirection, facilities::TrafficDirection::Upstream);
    EXPECT_EQ(sent.back().validity, secs(20));
    EXPECT_EQ(sent.back().destination.radius, 1000.0);
    // Repeated every 0.5 s for 20 s: those by 10 s.
    EXPECT_EQ(den(h, "b").denmsSent(), every(detected, secs(0.5), secs(10)).size());
}

TEST_F(DenTest, TrafficJamAheadOnALowAverageSpeed) {
    Harness h(loadFiles({{"services.xml", std::string(kServices)},
                         {"den-use-cases.xml", useCases(R"(<usecase type="TrafficJamAhead"/>)")}}));
    h.manager.stations().setPhaseSink(&phases);
    h.step(secs(0), {moving("crawl", 0, 5), moving("fast", 100, 30), moving("stand", 200, 0)});
    h.sim.run(secs(15));
    // Sampled every second from the first trigger; 10 s of samples 10 s later: average 5 m/s ≤ 30 km/h.
    const SimTime crawlSent = triggerFrom(h, "crawl", SimTime::zero()) + secs(10);
    EXPECT_EQ(phases.of("crawl").front(), "new@" + crawlSent.str() + " crawl:1");
    EXPECT_EQ(den(h, "fast").denmsSent(), 0u);
    // Standing (average 0) counts only with a jam heard of: crawl's DENM (cause 1) is one.
    EXPECT_EQ(phases.of("stand").size(), 2u);  // its memory's "new" of crawl:1, then its own
    // Its own once it has 10 s of samples and has heard crawl's DENM (a millisecond after it was sent).
    const SimTime standSent = triggerFrom(
        h, "stand",
        std::max(triggerFrom(h, "stand", SimTime::zero()) + secs(10), crawlSent + SimTime::fromMilliseconds(1)));
    EXPECT_EQ(phases.of("stand").back(), "new@" + standSent.str() + " stand:1");
    const auto& d = its.denms["fast"].front();
    EXPECT_EQ(d.cause, 1);
    EXPECT_EQ(d.validity, secs(60));
    EXPECT_EQ(d.trafficDirection, facilities::TrafficDirection::Upstream);
}

}  // namespace
}  // namespace sbsim::services::test
