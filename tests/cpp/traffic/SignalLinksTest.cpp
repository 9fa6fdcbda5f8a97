// SignalLinks by hand: which link a move from an approach lane onto a junction went through.
#include "sbsim/traffic/SignalLinks.h"

#include <gtest/gtest.h>

namespace sbsim::traffic {
namespace {

SignalLinks junction() {
    // Light J: link 0 straight (a_0 over :J_0_0 to b_0), link 1 left (a_1 over :J_1_0, where left
    // turns wait, and :J_4_0 to c_0); link 2 without internal lanes (d_0 to b_1).
    SignalLinks links;
    links.add({"J", 0}, "a_0", {":J_0_0"}, "b_0");
    links.add({"J", 1}, "a_1", {":J_1_0", ":J_4_0"}, "c_0");
    links.add({"J", 2}, "d_0", {}, "b_1");
    return links;
}

TEST(SignalLinks, MovesOntoTheJunctionNameTheirLink) {
    const SignalLinks links = junction();
    EXPECT_TRUE(links.isApproach("a_0"));
    EXPECT_FALSE(links.isApproach("b_0"));
    EXPECT_EQ(links.passed("a_0", ":J_0_0")->index, 0);
    EXPECT_EQ(links.passed("a_1", ":J_4_0")->index, 1);  // past the wait point in one step
    EXPECT_EQ(links.passed("a_0", ":J_4_0")->index, 1);  // changed lanes and passed in one step
    EXPECT_EQ(links.passed("d_0", "b_1")->index, 2);
    EXPECT_EQ(links.passed("a_0", "b_0")->signal, "J");
    EXPECT_FALSE(links.passed("a_0", "c_0"));        // no link from a_0 to c_0
    EXPECT_FALSE(links.passed(":J_1_0", ":J_4_0"));  // inside the junction: the line is behind
    EXPECT_FALSE(links.passed("b_0", "x_0"));
}

TEST(SignalLinks, TowardFindsTheLinkToAnEdge) {
    const SignalLinks links = junction();
    EXPECT_EQ(links.toward("a_1", "c")->index, 1);
    EXPECT_FALSE(links.toward("a_1", "b"));
    EXPECT_FALSE(links.toward("x_0", "b"));
}

}  // namespace
}  // namespace sbsim::traffic
