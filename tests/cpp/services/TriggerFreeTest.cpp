// A station whose services are all TriggerFree (the beacon) is not woken every interval while its
// facilities hold nothing; what it stores starts its clock again on the same grid, so it drops
// expired CAMs and DENMs, and reports the DENMs' expiry, at the very triggers a station with a
// triggered service (a counter) does.

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "ServicesTestSupport.h"
#include "sbsim/facilities/Cam.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/facilities/DenmPhase.h"
#include "sbsim/services/IndicatedTypes.h"
#include "sbsim/services/ServiceRegistry.h"

namespace sbsim::services::test {
namespace {

constexpr std::string_view kSilent = R"(<services><service type="Beacon" interval="1e9"/></services>)";
constexpr std::string_view kTriggered =
    R"(<services><service type="Beacon" interval="1e9"/><service type="TickCounter"/></services>)";

/// A service that is triggered (not TriggerFree) and takes no messages.
class TickCounter : public Service, public IndicatedTypes {
public:
    void trigger() override { ++ticks; }
    std::vector<std::string> indicatedTypes() const override { return {}; }
    static inline std::size_t ticks = 0;
};
SBSIM_REGISTER_SERVICE(TickCounter);

struct PhaseLog : facilities::DenmPhaseSink {
    std::vector<std::string> lines;
    void denmPhase(const facilities::DenmPhaseEvent& e) override {
        lines.push_back(e.station + " " + std::string(facilities::phaseName(e.phase)) + "@" + e.time.str() + " " +
                        e.action.str());
    }
};

facilities::DenmContent denm(std::uint32_t seq, double detection, double validity) {
    facilities::DenmContent d;
    d.action = {"s", seq};
    d.detectionTime = secs(detection);
    d.referenceTime = secs(detection);
    d.validity = secs(validity);
    d.cause = 6;
    d.destination.radius = 1000;
    return d;
}

std::unique_ptr<facilities::Cam> cam(double t) {
    facilities::CamContent c;
    c.station = "s";
    c.generationTime = secs(t);
    return std::make_unique<facilities::Cam>(c);
}

/// What station "a" went through: its DENM phases, and its LDM's size just before and just after
/// each instant of `checks`.
struct Seen {
    std::vector<std::string> phases;
    std::vector<std::size_t> ldmSizes;
    std::uint64_t events = 0;
};

/// "s" sends (the disc's latency: 1 ms) a DENM at 1 s (valid 0.5 s), then a CAM and a DENM (valid 2 s) at 5 s; "a"
/// hears them.
Seen run(std::string_view services, const std::vector<SimTime>& checks) {
    Harness h(services);
    PhaseLog log;
    h.manager.stations().setPhaseSink(&log);
    h.step(secs(0), {vehicle("s", 0, 0), vehicle("a", 10, 0)});
    h.at(secs(1), [&] { h.manager.middlewareOf("s")->send(std::make_unique<facilities::Denm>(denm(1, 1, 0.5))); });
    h.at(secs(5), [&] {
        h.manager.middlewareOf("s")->send(cam(5));
        h.manager.middlewareOf("s")->send(std::make_unique<facilities::Denm>(denm(2, 5, 2)));
    });
    Seen seen;
    for (const SimTime t : checks) {
        for (const SimTime at : {t - SimTime::fromNanoseconds(1), t + SimTime::fromNanoseconds(1)}) {
            h.at(at, [&] { seen.ldmSizes.push_back(h.manager.stations().find("a")->ldm.size()); });
        }
    }
    h.sim.run(secs(20));
    for (const std::string& line : log.lines) {
        if (line.starts_with("a ")) seen.phases.push_back(line);
    }
    seen.events = h.sim.eventCount();
    return seen;
}

/// Station "a"'s first trigger after `t` (its own clock: the harness's seed 0 and 0.1 s interval).
SimTime after(SimTime t) {
    SimTime at = Middleware::clockPhase(0, "a", secs(0.1));
    while (at <= t) at += secs(0.1);
    return at;
}

TEST(TriggerFree, AStationWithNothingToExpireIsNotWoken) {
    Harness h(kSilent);
    h.step(secs(0), {vehicle("a", 0, 0), vehicle("b", 10, 0)});
    h.sim.run(secs(10));
    // The step and each station's first trigger, where the clock stopped (the beacons' first
    // timers lie beyond: a phase in [0, 1e9) s); with a triggered service, 100 triggers a station.
    EXPECT_EQ(h.sim.eventCount(), 3u);
}

TEST(TriggerFree, WhatIsStoredExpiresAtTheTriggersOfATriggeredStation) {
    // "a"'s triggers just after the first DENM's expiry (1.5 s), the CAM's (5 s + 1.1 s) and the
    // second DENM's (7 s): an entry is dropped at the first trigger after its expiry.
    const SimTime denm1 = after(secs(1.5));
    const SimTime cam = after(secs(6.1));
    const SimTime denm2 = after(secs(7));
    const Seen silent = run(kSilent, {cam});
    TickCounter::ticks = 0;
    const Seen triggered = run(kTriggered, {cam});
    EXPECT_GT(TickCounter::ticks, 300u);  // both stations, every 0.1 s for 20 s

    const std::vector<std::string> expected = {"a new@1.001 s:1", "a expired@" + denm1.str() + " s:1",
                                               "a new@5.001 s:2", "a expired@" + denm2.str() + " s:2"};
    EXPECT_EQ(silent.phases, expected);
    EXPECT_EQ(triggered.phases, expected);
    EXPECT_EQ(silent.ldmSizes, (std::vector<std::size_t>{1, 0}));
    EXPECT_EQ(triggered.ldmSizes, silent.ldmSizes);
    // Woken twice, each time until its facilities were empty again: about 7 and 22 triggers, not 200.
    EXPECT_LT(silent.events + 150, triggered.events);
}

}  // namespace
}  // namespace sbsim::services::test
