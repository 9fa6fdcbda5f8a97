#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sbsim/kernel/StudyParameters.h"
#include "sbsim/radio/channel/RadioFile.h"
#include "sbsim/radio/propagation/LogDistanceLoss.h"

namespace sbsim::radio {
namespace {

/// A radio file in the test's own temporary folder.
class RadioFileTest : public ::testing::Test {
protected:
    std::filesystem::path write(const std::string& text) {
        dir_ = std::filesystem::temp_directory_path() /
               ("sbsim-radio-file-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::create_directories(dir_);
        const auto path = dir_ / "radio.toml";
        std::ofstream(path) << text;
        return path;
    }
    void TearDown() override {
        if (!dir_.empty()) std::filesystem::remove_all(dir_);
    }
    /// The message of the RadioFileError that reading `text` throws, and whether a parameter caused it.
    std::pair<std::string, bool> refusal(const std::string& text, const kernel::StudyParameters& parameters = {}) {
        const auto path = write(text);
        try {
            (void)readRadioFile(path, parameters);
        } catch (const RadioFileError& e) {
            std::string message = e.what();
            if (message.rfind(path.string(), 0) == 0) message.replace(0, path.string().size(), "FILE");
            return {message, e.fromParameter()};
        }
        return {"accepted", false};
    }

private:
    std::filesystem::path dir_;
};

TEST_F(RadioFileTest, NoFileGivesTheDefaults) {
    const ChannelSettings s = readRadioFile(std::nullopt, {});
    const ChannelSettings defaults;
    EXPECT_EQ(s.powerDbm, defaults.powerDbm);
    EXPECT_EQ(s.pathLoss, "winner-b1");
    EXPECT_TRUE(s.pathLossKeys.empty());
}

TEST_F(RadioFileTest, KeysSetTheSettingsAndParametersOverrideThem) {
    const auto path = write(
        "[phy]\npower_dbm = 30\n[propagation]\npath_loss = \"log-distance\"\nexponent = 3\n"
        "[mac]\nqueue_limit = 4\n[fer]\ntable = [[0, 1], [10, 0.1]]\n");
    ChannelSettings s = readRadioFile(path, {});
    EXPECT_EQ(s.powerDbm, 30);
    EXPECT_EQ(s.pathLoss, "log-distance");
    EXPECT_EQ(s.queueLimit, 4U);
    EXPECT_EQ(s.ferTable.size(), 2U);
    EXPECT_DOUBLE_EQ(s.makePathLoss()->lossDb(100), LogDistanceLoss(47.86, 1, 3).lossDb(100));

    kernel::StudyParameters parameters;
    parameters.add("radio_exponent=2.5");
    parameters.add("radio_path_loss=log-distance");
    parameters.add("radio_power_dbm=10");
    s = readRadioFile(path, parameters);
    EXPECT_EQ(s.powerDbm, 10);
    EXPECT_DOUBLE_EQ(s.makePathLoss()->lossDb(100), LogDistanceLoss(47.86, 1, 2.5).lossDb(100));
    EXPECT_TRUE(parameters.unread().empty());
}

TEST_F(RadioFileTest, RefusalsNameFileLineKeyAndProblem) {
    EXPECT_EQ(refusal("[phy]\npower = 23\n").first, "FILE:2: [phy] power: is not a radio setting (see README, Radio)");
    // A model key belongs to [propagation].
    EXPECT_EQ(refusal("[phy]\nexponent = 3\n").first,
              "FILE:2: [phy] exponent: is not a radio setting (see README, Radio)");
    EXPECT_EQ(refusal("[propagation]\n\npath_loss = \"moon\"\n").first,
              "FILE:3: [propagation] path_loss: must be " + PathLossModels::names());
    EXPECT_EQ(refusal("[propagation]\nexponent = \"steep\"\n").first,
              "FILE:2: [propagation] exponent: must be a number");
    EXPECT_EQ(refusal("[phy]\nrate_mbps = 7\n").first, "FILE: rate_mbps must be one of 3, 4.5, 6, 9, 12, 18, 24, 27");
    EXPECT_EQ(refusal("[propagation]\nenvironment_height = 2\n").first,
              "FILE: WINNER+ B1: antennas must be above the environment height");
    EXPECT_EQ(refusal("[fer]\ntable = [[0]]\n").first, "FILE: [fer] table: each row is [Eb/N0 dB, FER]");
    EXPECT_EQ(refusal("power_dbm = 3\n").first, "FILE: 'power_dbm' must be a [section]");
    EXPECT_EQ(refusal("[phy\n").first.rfind("FILE:1: ", 0), 0U);

    kernel::StudyParameters parameters;
    parameters.add("radio_power_dbm=hot");
    EXPECT_EQ(refusal("", parameters), std::make_pair(std::string("--param radio_power_dbm: must be a number"), true));
    kernel::StudyParameters model;
    model.add("radio_path_loss=moon");
    EXPECT_EQ(refusal("", model).first, "--param radio_path_loss: must be " + PathLossModels::names());
}

// Issue 29: keys took inf, NaN and absurd sizes, truncated fractions (queue_limit = nan was an
// undefined cast), and an integer a double cannot hold exactly ended in "bad optional access".
TEST_F(RadioFileTest, EveryNumberHasAKindAndARange) {
    EXPECT_EQ(refusal("[mac]\nqueue_limit = nan\n").first,
              "FILE:2: [mac] queue_limit: must be a whole number from 1 to 1e+06, got nan");
    EXPECT_EQ(refusal("[mac]\ncontention_window = 15.5\n").first,
              "FILE:2: [mac] contention_window: must be a whole number from 0 to 1023, got 15.5");
    EXPECT_EQ(refusal("[latency]\ndelay_s = inf\n").first,
              "FILE:2: [latency] delay_s: must be a number from 0 to 1000, got inf");
    EXPECT_EQ(refusal("[phy]\npower_dbm = 9007199254740993\n").first,
              "FILE:2: [phy] power_dbm: must be a number from -300 to 100, got 9.0072e+15");
    EXPECT_EQ(refusal("[obstacles]\nwall_db = -inf\n").first,
              "FILE:2: [obstacles] wall_db: must be a number from 0 to 1000, got -inf");
    EXPECT_EQ(refusal("[propagation]\npath_loss = \"log-distance\"\nexponent = nan\n").first,
              "FILE:3: [propagation] exponent: must be a number from -1e+09 to 1e+09, got nan");
    EXPECT_EQ(refusal("[fer]\ntable = [[0, 1], [10, 2]]\n").first,
              "FILE: [fer] table: each row is [Eb/N0 dB, FER], FER from 0 to 1");
    EXPECT_EQ(refusal("[phy]\npower_dbm = 20\n[mac]\naifsn = 3\nqueue_limit = 1000000\n").first, "accepted");

    kernel::StudyParameters fraction;
    fraction.add("radio_queue_limit=2.5");
    EXPECT_EQ(refusal("", fraction),
              std::make_pair(std::string("--param radio_queue_limit: must be a whole number from 1 to 1e+06, got 2.5"),
                             true));
}

}  // namespace
}  // namespace sbsim::radio
