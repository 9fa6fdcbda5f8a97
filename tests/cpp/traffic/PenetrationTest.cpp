#include "sbsim/traffic/Penetration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbsim::traffic {
namespace {

std::string id(int k) { return "veh" + std::to_string(k); }

int equippedAmong(const Penetration& p, int n) {
    int count = 0;
    for (int k = 0; k < n; ++k) count += p.equipped(id(k)) ? 1 : 0;
    return count;
}

TEST(Penetration, EverybodyByDefault) {
    const Penetration p;
    EXPECT_TRUE(p.everyone());
    EXPECT_EQ(equippedAmong(p, 1000), 1000);
    EXPECT_EQ(equippedAmong(Penetration(1.0, 7), 1000), 1000);
    EXPECT_EQ(equippedAmong(Penetration(0.0, 7), 1000), 0);
}

TEST(Penetration, TheShareOfVehiclesIsEquipped) {
    // 20,000 draws: the share lands within 1.5 points (more than 5 standard deviations).
    for (const double share : {0.1, 0.3, 0.5, 0.9}) {
        const double got = equippedAmong(Penetration(share, 42), 20000) / 20000.0;
        EXPECT_NEAR(got, share, 0.015) << "share " << share;
    }
}

TEST(Penetration, TheSameSeedEquipsTheSameVehiclesAndMoreShareOnlyAdds) {
    const Penetration low(0.3, 5), lowAgain(0.3, 5), high(0.6, 5), otherSeed(0.3, 6);
    int differ = 0;
    for (int k = 0; k < 5000; ++k) {
        EXPECT_EQ(low.equipped(id(k)), lowAgain.equipped(id(k)));
        if (low.equipped(id(k))) EXPECT_TRUE(high.equipped(id(k))) << id(k);
        differ += low.equipped(id(k)) != otherSeed.equipped(id(k)) ? 1 : 0;
    }
    // Independent draws disagree on 2 · 0.3 · 0.7 = 42 % of the vehicles.
    EXPECT_NEAR(differ / 5000.0, 0.42, 0.04);
}

TEST(Penetration, DrawsAreInTheUnitInterval) {
    const Penetration p(0.5, 1);
    for (int k = 0; k < 1000; ++k) {
        const double d = p.draw(id(k));
        EXPECT_GE(d, 0.0);
        EXPECT_LT(d, 1.0);
    }
    EXPECT_EQ(p.draw(""), p.draw(""));
}

TEST(Penetration, ShareOutsideZeroToOneIsRejected) {
    EXPECT_THROW(Penetration(-0.1, 1), std::invalid_argument);
    EXPECT_THROW(Penetration(1.5, 1), std::invalid_argument);
    EXPECT_THROW(Penetration(std::nan(""), 1), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::traffic
