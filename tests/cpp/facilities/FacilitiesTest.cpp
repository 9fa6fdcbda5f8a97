// The local dynamic map keeps each station's newest CAM for its lifetime; the DENM memory keeps
// the newest reference time per action id, ends events on termination and drops them at detection
// time + validity (600 s when absent); the geo-broadcast circle; the messages' sizes follow content.

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>
#include <vector>

#include "sbsim/facilities/Cam.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/facilities/DenmMemory.h"
#include "sbsim/facilities/LocalDynamicMap.h"
#include "sbsim/facilities/StationRegistry.h"

namespace sbsim::facilities {
namespace {

using kernel::SimTime;
SimTime secs(double s) { return SimTime::fromSeconds(s); }

CamContent cam(const std::string& station, double t, double x = 0) {
    CamContent c;
    c.station = station;
    c.generationTime = secs(t);
    c.position = {x, 0};
    return c;
}

// The station indices of the LDM tests (a registry's in a run).
radio::StationIds ids;

/// Takes `c` into `ldm` under its station's index.
void update(LocalDynamicMap& ldm, const CamContent& c, SimTime now) { ldm.update(ids.intern(c.station), c, now); }

DenmContent denm(const std::string& station, std::uint32_t seq, double detection, double reference,
                 std::optional<double> validity = std::nullopt) {
    DenmContent d;
    d.action = {station, seq};
    d.detectionTime = secs(detection);
    d.referenceTime = secs(reference);
    d.cause = 6;
    if (validity) d.validity = secs(*validity);
    return d;
}

TEST(LocalDynamicMap, KeepsTheNewestCamPerStationForItsLifetime) {
    LocalDynamicMap ldm;
    update(ldm, cam("a", 1.0, 10), secs(1.001));
    update(ldm, cam("b", 1.2, 20), secs(1.201));
    update(ldm, cam("a", 1.5, 15), secs(1.501));
    update(ldm, cam("a", 1.4, 99), secs(1.6));  // older than the one kept: ignored
    ASSERT_EQ(ldm.size(), 2u);
    EXPECT_DOUBLE_EQ(ldm.find("a")->cam.position.x(), 15);
    EXPECT_EQ(ldm.find("a")->age(secs(2.0)), secs(0.5));
    // b's CAM (t = 1.2) lives until 2.3 s, a's (1.5) until 2.6 s.
    ldm.dropExpired(secs(2.3));
    EXPECT_NE(ldm.find("b"), nullptr);
    ldm.dropExpired(secs(2.31));
    EXPECT_EQ(ldm.find("b"), nullptr);
    EXPECT_NE(ldm.find("a"), nullptr);
    EXPECT_EQ(ldm.count(secs(2.5), [](const auto&) { return true; }), 1u);
    EXPECT_EQ(ldm.count(secs(2.7), [](const auto&) { return true; }), 0u);  // past its lifetime, not yet dropped
    update(ldm, cam("c", 0.0), secs(2.0));                                  // already past its lifetime
    EXPECT_EQ(ldm.find("c"), nullptr);
}

TEST(LocalDynamicMap, DropsExactlyWhatABruteForceMapDrops) {
    // Many stations, CAMs at uneven intervals and drops at every trigger: the map keeps exactly the
    // entries whose last CAM is within its lifetime, as walking every entry would.
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int> station(0, 59);
    std::uniform_real_distribution<double> gap(0.0, 0.05);
    LocalDynamicMap ldm;
    std::map<std::string, SimTime> last;  // the model: station -> generation time of its last CAM
    double t = 0;
    std::size_t dropped = 0;
    for (int k = 0; k < 20000; ++k) {
        t += gap(rng);
        const std::string id = "s" + std::to_string(station(rng) * (k < 10000 ? 1 : 2));
        const double generated = t - gap(rng);  // a little older than its reception
        update(ldm, cam(id, generated), secs(t));
        if (generated + 1.1 >= t && (!last.count(id) || last[id] <= secs(generated))) last[id] = secs(generated);
        if (k % 7 == 0) {
            ldm.dropExpired(secs(t));
            for (auto it = last.begin(); it != last.end();) {
                if (it->second + LocalDynamicMap::kLifetime < secs(t)) {
                    it = last.erase(it);
                    ++dropped;
                } else {
                    ++it;
                }
            }
            ASSERT_EQ(ldm.size(), last.size()) << "t=" << t;
            for (const auto& [id, generated] : last) {
                ASSERT_EQ(ldm.find(id)->cam.generationTime, generated);
                ASSERT_EQ(ldm.find(ids.intern(id)), ldm.find(id));
            }
            for (const auto& [id, entry] : ldm.entries()) ASSERT_EQ(ldm.find(entry.stationIndex), &entry);
        }
    }
    EXPECT_GT(dropped, 100u);  // not vacuous
}

TEST(DenmMemory, NewestReferenceTimeWinsAndRepetitionsChangeNothing) {
    DenmMemory memory;
    EXPECT_EQ(memory.received(denm("x", 1, 10, 10), secs(10)), DenmPhase::New);
    EXPECT_EQ(memory.received(denm("x", 1, 10, 10), secs(11)), std::nullopt);  // repetition
    auto newer = denm("x", 1, 10, 12);
    newer.subcause = 3;
    EXPECT_EQ(memory.received(newer, secs(12)), DenmPhase::Update);
    EXPECT_EQ(memory.received(denm("x", 1, 10, 11), secs(13)), std::nullopt);  // older version, late
    ASSERT_NE(memory.find({"x", 1}), nullptr);
    EXPECT_EQ(memory.find({"x", 1})->denm.subcause, 3);
    EXPECT_EQ(memory.find({"x", 1})->firstHeardAt, secs(10));
    EXPECT_EQ(memory.received(denm("x", 2, 13, 13), secs(13)), DenmPhase::New);  // another event of x
    EXPECT_EQ(memory.received(denm("y", 1, 13, 13), secs(13)), DenmPhase::New);
    EXPECT_EQ(memory.size(), 3u);
    EXPECT_EQ(memory.count(6, secs(13)), 3u);
    EXPECT_EQ(memory.count(5, secs(13)), 0u);
}

TEST(DenmMemory, TerminationEndsTheEvent) {
    DenmMemory memory;
    memory.received(denm("x", 1, 10, 10), secs(10));
    auto cancel = denm("x", 1, 10, 20);
    cancel.termination = Termination::Cancellation;
    EXPECT_EQ(memory.received(cancel, secs(20)), DenmPhase::Terminate);
    EXPECT_EQ(memory.size(), 0u);
    EXPECT_EQ(memory.received(cancel, secs(21)), std::nullopt);  // nothing left to end
}

TEST(DenmMemory, ExpiresAtDetectionPlusValidity) {
    DenmMemory memory;
    memory.received(denm("x", 1, 10, 10, 2.0), secs(10));
    memory.received(denm("y", 1, 10, 15), secs(15));  // no validity: 600 s
    EXPECT_EQ(memory.dropExpired(secs(12)).size(), 0u);
    const auto dropped = memory.dropExpired(secs(12.001));
    ASSERT_EQ(dropped.size(), 1u);
    EXPECT_EQ(dropped[0].denm.action.station, "x");
    EXPECT_EQ(memory.dropExpired(secs(610)).size(), 0u);
    EXPECT_EQ(memory.dropExpired(secs(610.001)).size(), 1u);
    // A DENM heard after its expiry is not taken in.
    EXPECT_EQ(memory.received(denm("z", 1, 0, 0, 1.0), secs(5)), std::nullopt);
}

TEST(DenmMemory, DropsExactlyWhatABruteForceMapDropsWhateverItsEarliestExpiry) {
    // Random news, updates to sooner and later expiries, terminations and drops, against a plain map
    // walked on every drop: an event due at the memory's earliest expiry (which only skips walks)
    // is still dropped on time, and none is dropped early.
    std::mt19937 random(7);
    DenmMemory memory;
    std::map<ActionId, DenmContent> reference;
    std::size_t dropped = 0;
    for (int t = 1; t <= 4000; ++t) {
        const SimTime now = secs(t * 0.01);
        const int op = static_cast<int>(random() % 4);
        const auto seq = static_cast<std::uint32_t>(random() % 8);
        if (op == 3) {
            auto expired = memory.dropExpired(now);
            std::vector<ActionId> got;
            for (const auto& e : expired) got.push_back(e.denm.action);
            std::vector<ActionId> want;
            for (auto it = reference.begin(); it != reference.end();) {
                if (it->second.expiry() < now) {
                    want.push_back(it->first);
                    it = reference.erase(it);
                } else {
                    ++it;
                }
            }
            ASSERT_EQ(got, want) << "at " << now.str();
            dropped += got.size();
            continue;
        }
        const double validity = 0.05 + 0.01 * static_cast<double>(random() % 60);
        auto d = denm("x", seq, t * 0.01 - 0.01 * static_cast<double>(random() % 3), t * 0.01, validity);
        if (op == 2) d.termination = Termination::Cancellation;
        const auto it = reference.find(d.action);
        const bool older = it != reference.end() && d.referenceTime < it->second.referenceTime;
        if (d.termination) {
            if (it != reference.end() && !older) reference.erase(it);
        } else if (!(d.expiry() < now) && (it == reference.end() || it->second.referenceTime < d.referenceTime)) {
            reference[d.action] = d;
        }
        memory.received(d, now);
        ASSERT_LE(memory.earliestExpiry(),
                  reference.empty()
                      ? SimTime::max()
                      : std::min_element(reference.begin(), reference.end(), [](const auto& a, const auto& b) {
                            return a.second.expiry() < b.second.expiry();
                        })->second.expiry());
    }
    EXPECT_GT(dropped, 100u);  // not vacuous
}

struct Recorder : DenmPhaseSink {
    std::vector<DenmPhaseEvent> events;
    void denmPhase(const DenmPhaseEvent& e) override { events.push_back(e); }
};

TEST(StationRegistry, ReportsReceptionsAndExpiryPerStation) {
    StationRegistry stations;
    Recorder sink;
    stations.setPhaseSink(&sink);
    Denm message(denm("x", 7, 1, 1, 1.0));
    message.store(stations, "r1", secs(1.1));
    message.store(stations, "r1", secs(1.2));  // repetition: nothing
    message.store(stations, "r2", secs(1.1));
    stations.dropExpired("r1", secs(3));
    ASSERT_EQ(sink.events.size(), 3u);
    EXPECT_EQ(phaseName(sink.events[0].phase), "new");
    EXPECT_EQ(sink.events[0].station, "r1");
    EXPECT_EQ(sink.events[0].action.str(), "x:7");
    EXPECT_EQ(sink.events[2].phase, DenmPhase::Expired);
    EXPECT_EQ(stations.find("r1")->denms.size(), 0u);
    EXPECT_EQ(stations.find("r2")->denms.size(), 1u);
    stations.remove("r2");
    EXPECT_EQ(stations.find("r2"), nullptr);
}

TEST(GeoCircle, HoldsPointsUpToItsRadius) {
    const GeoCircle area{{100, 0}, 50};
    EXPECT_TRUE(area.contains({100, 0}));
    EXPECT_TRUE(area.contains({150, 0}));
    EXPECT_FALSE(area.contains({150.01, 0}));
    EXPECT_FALSE(area.contains({136, 36}));  // 50.9 m away
    Denm d(denm("x", 1, 0, 0));
    d = Denm([] {
        auto c = denm("x", 1, 0, 0);
        c.destination = {{100, 0}, 50};
        return c;
    }());
    EXPECT_TRUE(d.reaches({60, 20}));
    EXPECT_FALSE(d.reaches({40, 0}));
}

TEST(Messages, SizesFollowTheContent) {
    CamContent c = cam("a", 0);
    EXPECT_EQ(Cam(c).byteSize(), Cam::kHighFrequencyBytes);
    c.lowFrequency = CamLowFrequency{};
    const std::size_t withEmptyHistory = Cam(c).byteSize();
    EXPECT_GT(withEmptyHistory, Cam::kHighFrequencyBytes);
    c.lowFrequency->pathHistory.resize(3);
    EXPECT_EQ(Cam(c).byteSize(), withEmptyHistory + 3 * 7);

    DenmContent d = denm("x", 3, 0, 0);
    d.subcause = 2;
    const std::size_t plain = Denm(d).byteSize();
    d.impactReduction = ImpactReduction::Request;
    EXPECT_GT(Denm(d).byteSize(), plain);
    d.termination = Termination::Cancellation;
    EXPECT_LT(Denm(d).byteSize(), plain);
    const auto fields = Denm(d).traceFields();
    ASSERT_EQ(fields.size(), 3u);
    EXPECT_EQ(fields[0].name, "cause");
    EXPECT_EQ(std::get<std::int64_t>(fields[0].value), 6);
    EXPECT_EQ(std::get<std::int64_t>(fields[1].value), 2);
    EXPECT_EQ(std::get<std::string>(fields[2].value), "x:3");
}

}  // namespace
}  // namespace sbsim::facilities
