#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "sbsim/radio/propagation/FreeSpaceLoss.h"
#include "sbsim/radio/propagation/LogDistanceLoss.h"
#include "sbsim/radio/propagation/PathLossModels.h"
#include "sbsim/radio/propagation/TwoRayGroundLoss.h"
#include "sbsim/radio/propagation/WinnerB1Loss.h"

namespace sbsim::radio {
namespace {

constexpr double kF = 5.89e9;

TEST(PathLossModels, TheBuiltInModelsAreRegisteredOnce) {
    for (const char* name : {"free-space", "log-distance", "two-ray-ground", "winner-b1"})
        EXPECT_EQ(PathLossModels::all().count(name), 1U) << name;
    EXPECT_TRUE(PathLossModels::conflicts().empty());
    for (const char* key :
         {"antenna_height", "environment_height", "reference_loss_db", "reference_distance", "exponent"})
        EXPECT_EQ(PathLossModels::keys().count(key), 1U) << key;
}

TEST(PathLossModels, NamesReadAsAListInNameOrder) {
    std::string expected;
    std::size_t k = 0;
    for (const auto& [name, model] : PathLossModels::all()) {
        if (k > 0) expected += k + 1 == PathLossModels::all().size() ? " or " : ", ";
        expected += name;
        ++k;
    }
    EXPECT_EQ(PathLossModels::names(), expected);
}

TEST(PathLossModels, EveryModelBuildsFromItsDefaultsAndLosesMoreFartherAway) {
    for (const auto& [name, model] : PathLossModels::all()) {
        const auto loss = PathLossModels::make(name, kF, {});
        ASSERT_NE(loss, nullptr) << name;
        const double near = loss->lossDb(10);
        const double far = loss->lossDb(1000);
        EXPECT_TRUE(std::isfinite(near) && std::isfinite(far)) << name;
        EXPECT_GT(far, near) << name;
    }
}

TEST(PathLossModels, EveryModelsBatchGivesItsLossesOneByOneExactly) {
    // Below 1 m, around each law's breakpoint or crossover (WINNER+ B1 ~ 79 m, two-ray ~ 555 m at
    // the default 1.5 m) and out to the far tier: the batch is the channel's hot path, so bit for bit.
    std::vector<double> distances{0.25, 1.0, 1.5, 3.7, 10.0, 42.0};
    for (double d = 60; d < 1500; d *= 1.0137) distances.push_back(d);
    for (const auto& [name, model] : PathLossModels::all()) {
        const auto loss = PathLossModels::make(name, kF, {});
        std::vector<double> out(distances.size(), -1.0);
        loss->lossesDb(distances, out);
        for (std::size_t k = 0; k < distances.size(); ++k)
            EXPECT_EQ(out[k], loss->lossDb(distances[k])) << name << " at " << distances[k] << " m";
    }
}

TEST(PathLossModels, KeysSetOverrideTheDefaultsAndOthersAreIgnored) {
    const PathLossModels::Keys set{{"antenna_height", 2.5}, {"exponent", 3.0}};
    EXPECT_DOUBLE_EQ(PathLossModels::make("winner-b1", kF, set)->lossDb(300), WinnerB1Loss(kF, 2.5, 0.5).lossDb(300));
    EXPECT_DOUBLE_EQ(PathLossModels::make("winner-b1", kF, {})->lossDb(300), WinnerB1Loss(kF, 1.5, 0.5).lossDb(300));
    EXPECT_DOUBLE_EQ(PathLossModels::make("two-ray-ground", kF, set)->lossDb(900),
                     TwoRayGroundLoss(kF, 2.5, 2.5).lossDb(900));
    EXPECT_DOUBLE_EQ(PathLossModels::make("log-distance", kF, set)->lossDb(100),
                     LogDistanceLoss(47.86, 1, 3).lossDb(100));
    EXPECT_DOUBLE_EQ(PathLossModels::make("free-space", kF, set)->lossDb(100), FreeSpaceLoss(kF).lossDb(100));
}

TEST(PathLossModels, UnknownNamesAndBadValuesAreRefused) {
    try {
        (void)PathLossModels::make("moon", kF, {});
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "must be " + PathLossModels::names());
    }
    EXPECT_THROW((void)PathLossModels::make("winner-b1", kF, {{"environment_height", 2.0}}), std::invalid_argument);
    EXPECT_THROW((void)PathLossModels::make("log-distance", kF, {{"exponent", 0.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::radio
