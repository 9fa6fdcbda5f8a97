#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "sbsim/radio/CertificatePolicy.h"
#include "sbsim/radio/LastHeard.h"

namespace sbsim::radio {
namespace {

using kernel::SimTime;
using Index = LastHeard::Index;

TEST(LastHeard, OneStationAtATime) {
    LastHeard heard;
    EXPECT_FALSE(heard.hear(7, SimTime::fromMilliseconds(10)));
    EXPECT_FALSE(heard.hear(3, SimTime::fromMilliseconds(20)));
    EXPECT_EQ(heard.hear(7, SimTime::fromMilliseconds(30)), SimTime::fromMilliseconds(10));
    EXPECT_EQ(heard.hear(3, SimTime::fromMilliseconds(40)), SimTime::fromMilliseconds(20));
    EXPECT_EQ(heard.size(), 2u);
    heard.forgetBefore(SimTime::fromMilliseconds(35));
    EXPECT_EQ(heard.size(), 1u);
    EXPECT_FALSE(heard.hear(7, SimTime::fromMilliseconds(50)));
    EXPECT_EQ(heard.hear(3, SimTime::fromMilliseconds(60)), SimTime::fromMilliseconds(40));
}

// Frames of random receivers (ascending runs, shuffled, gaps, newcomers, forgetting) against a
// std::map holding the same history: hearAll reports exactly the stations a map would call unknown.
TEST(LastHeard, AFrameAtOnceAnswersAsOneStationAtATime) {
    std::mt19937 random(5);
    LastHeard heard;
    std::map<Index, SimTime> reference;
    const SimTime window = SimTime::fromMilliseconds(500);
    for (int frame = 0; frame < 400; ++frame) {
        const SimTime now = SimTime::fromMilliseconds(10 * frame);
        std::vector<Index> stations;
        const Index base = static_cast<Index>(random() % 300);
        for (Index s = base; s < base + 400; ++s) {
            if (random() % 3 == 0) stations.push_back(s);
        }
        if (frame % 4 == 1) std::shuffle(stations.begin(), stations.end(), random);
        if (frame % 4 == 2 && stations.size() > 10) std::swap(stations[2], stations[stations.size() - 3]);
        std::vector<Index> unknown;
        heard.hearAll(stations, now, now - window, unknown);
        std::vector<Index> expected;
        for (const Index s : stations) {
            const auto it = reference.find(s);
            if (it == reference.end() || it->second < now - window) expected.push_back(s);
            reference[s] = now;
        }
        ASSERT_EQ(unknown, expected) << "frame " << frame;
        if (frame % 50 == 49) {
            const SimTime before = now - SimTime::fromMilliseconds(200);
            heard.forgetBefore(before);
            std::erase_if(reference, [&](const auto& entry) { return entry.second < before; });
        }
        ASSERT_EQ(heard.size(), reference.size());
    }
    // Single receptions see the same history.
    for (const auto& [s, t] : reference) EXPECT_EQ(heard.hear(s, SimTime::fromSeconds(10)), t);
}

TEST(CertificatePolicy, AFrameAtOnceDecidesAsItsReceptionsOneByOne) {
    // Each receiver's next CAM carries the certificate when it heard a new sender, one by one or
    // the frame at once.
    CertificatePolicy single, frame;
    std::vector<CertificatePolicy::Index> receivers;
    for (const char* name : {"r1", "r2", "r3", "r4"}) {
        for (CertificatePolicy* policy : {&single, &frame}) {
            policy->index(name);
            policy->sign(name, SecurityProfile::Cam, SimTime::zero());
        }
        receivers.push_back(frame.index(name));
    }
    for (CertificatePolicy* policy : {&single, &frame}) {
        policy->heard("r1", "s", SecurityProfile::Cam, SimTime::zero());
        policy->sign("r1", SecurityProfile::Cam, SimTime::fromMilliseconds(50));  // the request answered
    }
    const SimTime now = SimTime::fromMilliseconds(100);
    for (const char* name : {"r3", "r1", "r4", "r2"}) single.heard(name, "s", SecurityProfile::Cam, now);
    const std::vector<CertificatePolicy::Index> shuffled{receivers[2], receivers[0], receivers[3], receivers[1]};
    frame.heardAll(shuffled, frame.index("s"), SecurityProfile::Cam, now);
    const SimTime next = SimTime::fromMilliseconds(200);
    for (const char* name : {"r1", "r2", "r3", "r4"}) {
        const SignerIdentifier one = single.sign(name, SecurityProfile::Cam, next);
        EXPECT_EQ(frame.sign(name, SecurityProfile::Cam, next), one) << name;
        // r1 knew s already; the others heard a new station.
        EXPECT_EQ(one, std::string(name) == "r1" ? SignerIdentifier::Digest : SignerIdentifier::Certificate) << name;
    }
    EXPECT_EQ(frame.remembered(), single.remembered());
}

}  // namespace
}  // namespace sbsim::radio
