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

/// A neighbourhood drawn afresh: each of the stations 0 .. n - 1 with probability one half, ascending.
std::vector<Index> aboutHalfOf(Index n, std::mt19937& random) {
    std::vector<Index> stations;
    for (Index s = 0; s < n; ++s) {
        if (random() % 2 == 0) stations.push_back(s);
    }
    return stations;
}

/// The randomized tests' three answers side by side: the table under test, one that walks every
/// frame in full (hearAll) and a std::map of when each station was last heard.
struct ThreeAnswers {
    LastHeard heard, walked;
    std::map<Index, SimTime> reference;
    SimTime window = SimTime::fromMilliseconds(500);
    std::string where;  // the seed and step, for the failure messages

    /// A frame of `list` at `at`: the tested table's unknown stations as the full walk's and the map's.
    bool frame(const LastHeard::List& list, SimTime at, const std::string& what) {
        std::vector<Index> unknown, full;
        heard.hearList(list, at, at - window, unknown);
        walked.hearAll(*list, at, at - window, full);
        EXPECT_EQ(unknown, full) << where << " " << what;
        std::vector<Index> expected;
        for (const Index s : *list) {
            const auto it = reference.find(s);
            if (it == reference.end() || it->second < at - window) expected.push_back(s);
            reference[s] = at;
        }
        EXPECT_EQ(unknown, expected) << where << " " << what;
        return !::testing::Test::HasFailure();
    }
    /// The sender's own frame to `own`, a list of its own (hearAll on both tables).
    bool ownFrame(const std::vector<Index>& own, SimTime at) {
        std::vector<Index> unknown, full;
        heard.hearAll(own, at, at - window, unknown);
        walked.hearAll(own, at, at - window, full);
        EXPECT_EQ(unknown, full) << where << " (own frame)";
        for (const Index s : own) reference[s] = at;
        return !::testing::Test::HasFailure();
    }
    /// One reception of `s` alone.
    bool hearOne(Index s, SimTime at) {
        EXPECT_EQ(heard.hear(s, at), walked.hear(s, at)) << where << " station " << s;
        reference[s] = at;
        return !::testing::Test::HasFailure();
    }
    void forget(SimTime before) {
        heard.forgetBefore(before);
        walked.forgetBefore(before);
        std::erase_if(reference, [&](const auto& entry) { return entry.second < before; });
    }
    /// After the run: both tables remember exactly the map's stations, at the map's times.
    void expectSameHistory(SimTime end) {
        heard.forgetBefore(SimTime::zero());
        ASSERT_EQ(heard.size(), reference.size()) << where;
        for (const auto& [s, t] : reference) {
            EXPECT_EQ(heard.hear(s, end), t) << where << " station " << s;
            EXPECT_EQ(walked.hear(s, end), t) << where << " station " << s;
        }
    }
};

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

// A sender's frames of a step share one list (a medium's receivers of the step): its repeats only
// note their time. Lists repeated, changed, left for longer than the window, mixed with single
// receptions, frames of their own and forgetting, against a std::map holding the same history.
TEST(LastHeard, RepeatsOfAListAnswerAsAWalkPerFrame) {
    std::mt19937 random(11);
    LastHeard heard;
    std::map<Index, SimTime> reference;
    const SimTime window = SimTime::fromMilliseconds(500);
    const auto expectFrame = [&](const std::vector<Index>& stations, SimTime now, const std::vector<Index>& unknown) {
        std::vector<Index> expected;
        for (const Index s : stations) {
            const auto it = reference.find(s);
            if (it == reference.end() || it->second < now - window) expected.push_back(s);
            reference[s] = now;
        }
        return unknown == expected;
    };
    LastHeard::List list;
    int repeats = 0, lazy = 0;
    SimTime now = SimTime::zero();
    for (int frame = 0; frame < 2000; ++frame) {
        // Mostly 10 ms apart; now and then a pause longer than the window, so a repeat must walk.
        now = now + SimTime::fromMilliseconds(random() % 40 == 0 ? 700 : 10);
        const unsigned pick = random() % 20;
        if (list == nullptr || pick < 2) {
            auto fresh = std::make_shared<std::vector<Index>>();
            const Index base = static_cast<Index>(random() % 300);
            for (Index s = base; s < base + 300; ++s) {
                if (random() % 3 == 0) fresh->push_back(s);
            }
            if (pick == 1) std::shuffle(fresh->begin(), fresh->end(), random);
            list = fresh;
        } else if (pick == 2) {
            // A frame of its own (stationary stations in range) between the list's frames.
            std::vector<Index> own;
            for (Index s = static_cast<Index>(random() % 50); s < 450; s += 1 + random() % 20) own.push_back(s);
            std::vector<Index> unknown;
            heard.hearAll(own, now, now - window, unknown);
            ASSERT_TRUE(expectFrame(own, now, unknown)) << "frame " << frame << " (own list)";
            continue;
        } else if (pick == 3) {
            // A single reception reads the time the repeats noted.
            const Index s = list->empty() ? 0 : (*list)[random() % list->size()];
            const auto it = reference.find(s);
            const std::optional<SimTime> expected =
                it == reference.end() ? std::nullopt : std::optional<SimTime>(it->second);
            ASSERT_EQ(heard.hear(s, now), expected) << "frame " << frame << " station " << s;
            reference[s] = now;
            continue;
        } else {
            ++repeats;
        }
        std::vector<Index> unknown;
        heard.hearList(list, now, now - window, unknown);
        if (heard.pending()) ++lazy;
        ASSERT_TRUE(expectFrame(*list, now, unknown)) << "frame " << frame;
        if (frame % 97 == 96) {
            // Now and then just before the list's last frames: what they noted must survive.
            const SimTime before = now - SimTime::fromMilliseconds(frame % 2 == 0 ? 200 : 15);
            heard.forgetBefore(before);
            std::erase_if(reference, [&](const auto& entry) { return entry.second < before; });
        }
        ASSERT_EQ(heard.size(), reference.size());
    }
    EXPECT_GT(lazy, repeats / 2);  // the repeats did take the lazy path
    // What the repeats noted is written before it is read.
    heard.forgetBefore(SimTime::zero());
    for (const auto& [s, t] : reference) EXPECT_EQ(heard.hear(s, now + SimTime::fromSeconds(10)), t) << s;
}

// A sender's list of the next step: the last with a few stations gone and a few come (at random
// places), now and then two neighbours swapped, a list reshuffled, a long pause, a frame of its
// own, a single reception or forgetting between. The difference's path answers as a full walk per
// frame (a LastHeard told by hearAll) and as a std::map, and leaves the same history.
TEST(LastHeard, AListTakenByItsDifferenceAnswersAsAFullWalk) {
    for (const unsigned seed : {1u, 2u, 3u}) {
        std::mt19937 random(seed);
        ThreeAnswers answers;
        std::vector<Index> current = aboutHalfOf(400, random);
        SimTime now = SimTime::zero();
        std::size_t lists = 0;
        for (int step = 0; step < 600; ++step) {
            answers.where = "seed " + std::to_string(seed) + " step " + std::to_string(step);
            const unsigned pick = random() % 40;
            if (pick == 0) {
                std::shuffle(current.begin(), current.end(), random);
            } else if (pick == 1) {
                current = aboutHalfOf(400, random);  // another neighbourhood entirely
            } else {
                // A few gone, a few come (stations not in the list, some heard before, some never).
                for (unsigned gone = random() % 6; gone > 0 && !current.empty(); --gone)
                    current.erase(current.begin() + static_cast<std::ptrdiff_t>(random() % current.size()));
                for (unsigned come = random() % 6; come > 0; --come) {
                    const Index s = static_cast<Index>(random() % 500);
                    if (std::find(current.begin(), current.end(), s) != current.end()) continue;
                    current.insert(current.begin() + static_cast<std::ptrdiff_t>(random() % (current.size() + 1)), s);
                }
                if (current.size() > 2 && random() % 4 == 0) {
                    const std::size_t k = random() % (current.size() - 1);
                    std::swap(current[k], current[k + 1]);
                }
            }
            const auto list = std::make_shared<const std::vector<Index>>(current);
            ++lists;
            // Steps of 100 ms, frames 10 ms apart; a pause longer than the window now and then.
            now = now + SimTime::fromMilliseconds(random() % 30 == 0 ? 650 : 100);
            for (unsigned frame = 0, frames = 1 + random() % 10; frame < frames; ++frame) {
                const SimTime at = now + SimTime::fromMilliseconds(10 * frame);
                ASSERT_TRUE(answers.frame(list, at, "frame " + std::to_string(frame)));
            }
            const unsigned between = random() % 25;
            const SimTime later = now + SimTime::fromMilliseconds(95);
            if (between == 0) {
                ASSERT_TRUE(answers.ownFrame({static_cast<Index>(random() % 500), 450, 460}, later));
            } else if (between == 1) {
                ASSERT_TRUE(answers.hearOne(static_cast<Index>(random() % 500), later));
            } else if (between == 2) {
                answers.forget(now - SimTime::fromMilliseconds(random() % 2 == 0 ? 300 : 5));
            }
            ASSERT_EQ(answers.heard.size(), answers.walked.size()) << answers.where;
        }
        // Most lists took the difference's path, and the history it left is the full walks'.
        EXPECT_GT(answers.heard.differences(), lists / 2) << "seed " << seed;
        answers.expectSameHistory(now + SimTime::fromSeconds(10));
    }
}

// The medium's path: a sender's next list compared with its last once (compare), the last shared
// again when equal, else the new list expected (expect) so its frames take that split. Lists change
// by a few stations or many (past the split's limit), mostly ascending, now and then reshuffled;
// a comparison now and then not followed by its list's frames (a hint gone stale), frames of
// another list, single receptions and forgetting between. Against a full walk per frame (hearAll)
// and a std::map, frame by frame and the history left.
TEST(LastHeard, AListComparedByTheMediumAnswersAsAFullWalk) {
    for (const unsigned seed : {4u, 5u, 6u, 7u}) {
        std::mt19937 random(seed);
        ThreeAnswers answers;
        LastHeard& heard = answers.heard;
        std::vector<Index> current = aboutHalfOf(600, random);
        LastHeard::List last;
        SimTime now = SimTime::zero();
        std::size_t lists = 0, same = 0;
        for (int step = 0; step < 800; ++step) {
            answers.where = "seed " + std::to_string(seed) + " step " + std::to_string(step);
            const unsigned pick = random() % 50;
            if (pick == 0) {
                std::shuffle(current.begin(), current.end(), random);
            } else if (pick == 1) {
                std::sort(current.begin(), current.end());
            } else if (pick < 4) {
                // Many changed: past a quarter of the list.
                current = aboutHalfOf(600, random);
            } else if (pick < 12) {
                // Unchanged: the medium shares the last list again.
            } else {
                // A few to some tens gone and come, ascending where the list was.
                const unsigned changes = random() % 4 == 0 ? 40 : 6;
                for (unsigned gone = random() % changes; gone > 0 && !current.empty(); --gone)
                    current.erase(current.begin() + static_cast<std::ptrdiff_t>(random() % current.size()));
                for (unsigned come = random() % changes; come > 0; --come) {
                    const Index s = static_cast<Index>(random() % 700);
                    if (std::find(current.begin(), current.end(), s) != current.end()) continue;
                    const auto at = std::upper_bound(current.begin(), current.end(), s);
                    current.insert(random() % 8 == 0
                                       ? current.begin() + static_cast<std::ptrdiff_t>(random() % (current.size() + 1))
                                       : at,
                                   s);
                }
            }
            // As DiscMedium::takeReceivers: the comparison decides whether the last list goes again.
            LastHeard::List list;
            if (last != nullptr && heard.compare(*last, current)) {
                ASSERT_EQ(*last, current) << answers.where;
                list = last;
                ++same;
            } else {
                if (last != nullptr) ASSERT_NE(*last, current) << answers.where;
                list = std::make_shared<const std::vector<Index>>(current);
                if (last != nullptr && random() % 10 != 0) heard.expect(last, list);
                ++lists;
            }
            now = now + SimTime::fromMilliseconds(random() % 30 == 0 ? 650 : 100);
            if (random() % 20 == 0) {
                // The comparison made, but another list comes first (a frame of the step before
                // still on the air, or one of its own).
                if (last != nullptr && random() % 2 == 0) {
                    ASSERT_TRUE(answers.frame(last, now, "(late)"));
                } else {
                    ASSERT_TRUE(answers.ownFrame({static_cast<Index>(random() % 700), 650, 660}, now));
                }
            }
            // Now and then none of the list's frames comes (their receivers left): the next
            // comparison is then against a list the table never held.
            const unsigned frames = random() % 15 == 0 ? 0 : 1 + random() % 10;
            for (unsigned frame = 0; frame < frames; ++frame) {
                const SimTime at = now + SimTime::fromMilliseconds(1 + 9 * frame);
                ASSERT_TRUE(answers.frame(list, at, "frame " + std::to_string(frame)));
            }
            last = list;
            const unsigned between = random() % 30;
            const SimTime later = now + SimTime::fromMilliseconds(95);
            if (between == 0) {
                ASSERT_TRUE(answers.hearOne(static_cast<Index>(random() % 700), later));
            } else if (between == 1) {
                answers.forget(now - SimTime::fromMilliseconds(random() % 2 == 0 ? 300 : 5));
            }
            ASSERT_EQ(heard.size(), answers.walked.size()) << answers.where;
        }
        // The paths were taken: lists shared again, and most new ones by their difference.
        EXPECT_GT(same, 50u) << "seed " << seed;
        EXPECT_GT(heard.differences(), lists / 2) << "seed " << seed;
        answers.expectSameHistory(now + SimTime::fromSeconds(10));
    }
}

TEST(LastHeard, ARepeatAfterTheWindowFindsItsStationsUnknown) {
    LastHeard heard;
    const auto list = std::make_shared<const std::vector<Index>>(std::vector<Index>{2, 5, 9});
    const SimTime window = SimTime::fromMilliseconds(500);
    std::vector<Index> unknown;
    heard.hearList(list, SimTime::fromMilliseconds(100), SimTime::fromMilliseconds(100) - window, unknown);
    EXPECT_EQ(unknown, (std::vector<Index>{2, 5, 9}));
    unknown.clear();
    heard.hearList(list, SimTime::fromMilliseconds(400), SimTime::fromMilliseconds(400) - window, unknown);
    EXPECT_TRUE(unknown.empty());
    EXPECT_TRUE(heard.pending());
    // 500 ms after the noted 400 ms: still known; 501 ms: unknown again.
    heard.hearList(list, SimTime::fromMilliseconds(900), SimTime::fromMilliseconds(900) - window, unknown);
    EXPECT_TRUE(unknown.empty());
    heard.hearList(list, SimTime::fromMilliseconds(1401), SimTime::fromMilliseconds(1401) - window, unknown);
    EXPECT_EQ(unknown, (std::vector<Index>{2, 5, 9}));
    // Another list writes the notes out first: 5 was heard at 1401 ms.
    unknown.clear();
    heard.hearAll(std::vector<Index>{5, 7}, SimTime::fromMilliseconds(1500), SimTime::fromMilliseconds(1500) - window,
                  unknown);
    EXPECT_EQ(unknown, (std::vector<Index>{7}));
    EXPECT_FALSE(heard.pending());
    EXPECT_EQ(heard.hear(9, SimTime::fromMilliseconds(1600)), SimTime::fromMilliseconds(1401));
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

// Ten frames a step from each of a few senders, each step's list shared by its frames (as the disc
// model hands them): the certificates signed are those of a policy told each reception one by one.
TEST(CertificatePolicy, SharedListsDecideAsReceptionsOneByOne) {
    std::mt19937 random(3);
    CertificatePolicy single, shared;
    std::vector<std::string> names;
    for (int k = 0; k < 40; ++k) names.push_back("v" + std::to_string(k));
    for (const std::string& name : names) {
        EXPECT_EQ(single.index(name), shared.index(name));
    }
    std::map<int, LastHeard::List> lists;
    int certificates = 0;
    for (int step = 0; step < 60; ++step) {
        // Steps of 1 s, a pause of 25 s now and then (past kForgetAfter: all forgotten).
        const SimTime begin = SimTime::fromSeconds(step % 20 == 19 ? step + 25 : step);
        for (int sender = 0; sender < 5; ++sender) {
            auto list = std::make_shared<std::vector<CertificatePolicy::Index>>();
            for (CertificatePolicy::Index s = 0; s < names.size(); ++s) {
                if (static_cast<int>(s) != sender && random() % 2 == 0) list->push_back(s);
            }
            lists[sender] = list;
        }
        for (int frame = 0; frame < 10; ++frame) {
            for (int sender = 0; sender < 5; ++sender) {
                const SimTime now = begin + SimTime::fromMilliseconds(100 * frame + 7 * sender);
                for (const CertificatePolicy::Index s : *lists[sender])
                    single.heard(s, static_cast<CertificatePolicy::Index>(sender), SecurityProfile::Cam, now);
                shared.heardAll(lists[sender], static_cast<CertificatePolicy::Index>(sender), SecurityProfile::Cam,
                                now);
                // Every station signs a CAM now and then.
                const auto signer = static_cast<CertificatePolicy::Index>(random() % names.size());
                const SignerIdentifier one = single.sign(signer, SecurityProfile::Cam, now);
                ASSERT_EQ(shared.sign(signer, SecurityProfile::Cam, now), one)
                    << "step " << step << " frame " << frame << " sender " << sender;
                if (one == SignerIdentifier::Certificate) ++certificates;
            }
        }
        ASSERT_EQ(shared.remembered(), single.remembered()) << "step " << step;
    }
    EXPECT_GT(certificates, 0);
}

}  // namespace
}  // namespace sbsim::radio
