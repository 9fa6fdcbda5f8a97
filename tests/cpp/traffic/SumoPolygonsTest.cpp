// The polygons SUMO loads from additional files, read back for story scripts.
#include "sbsim/traffic/SumoPolygons.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "SumoTestSupport.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::test {
namespace {

namespace fs = std::filesystem;
using traffic::SumoPolygons;

TEST(SumoPolygons, UnknownMessageNamesTheKnownIds) {
    EXPECT_EQ(SumoPolygons::unknownMessage("front", {"a", "b"}), "SUMO has no polygon 'front' (it has: a, b)");
    EXPECT_EQ(SumoPolygons::unknownMessage("front", {}),
              "SUMO has no polygon 'front' (it loaded none: polygons come from <poly> elements in the sumocfg's "
              "additional-files)");
    std::vector<std::string> many;
    for (int i = 0; i < 12; ++i) many.push_back("p" + std::to_string(i));
    EXPECT_EQ(SumoPolygons::unknownMessage("x", many),
              "SUMO has no polygon 'x' (it has 12: p0, p1, p2, p3, p4, p5, p6, p7, p8, p9, ...)");
}

TEST(SumoPolygons, NeedLoadedSumo) { EXPECT_THROW(SumoPolygons::ids(), std::logic_error); }

TEST(SumoPolygons, ShapesFromTheAdditionalFiles) {
    const fs::path file =
        fs::temp_directory_path() / ("sbsim-test-polygons-" + std::to_string(static_cast<long>(::getpid())) + ".xml");
    std::ofstream(file) << R"(<additional>
    <poly id="district" type="area" color="0,0,255" fill="1" shape="10,20 110,20 110,90.5 10,90.5"/>
    <poly id="another" color="red" shape="0,0 5,0 5,5"/>
</additional>
)";
    traffic::SumoSettings settings = scenarioSettings();
    settings.extraOptions = {"--additional-files", file.string()};
    {
        traffic::SumoBridge bridge(settings);
        bridge.load();
        EXPECT_EQ(SumoPolygons::ids(), (std::vector<std::string>{"another", "district"}));
        const std::vector<Eigen::Vector2d> shape = SumoPolygons::shape("district");
        ASSERT_EQ(shape.size(), 4u);  // as written: SUMO does not close it
        EXPECT_EQ(shape[0], Eigen::Vector2d(10, 20));
        EXPECT_EQ(shape[1], Eigen::Vector2d(110, 20));
        EXPECT_EQ(shape[2], Eigen::Vector2d(110, 90.5));
        EXPECT_EQ(shape[3], Eigen::Vector2d(10, 90.5));
        try {
            (void)SumoPolygons::shape("front");
            FAIL() << "an unknown polygon was found";
        } catch (const std::invalid_argument& e) {
            EXPECT_STREQ(e.what(), "SUMO has no polygon 'front' (it has: another, district)");
        }
    }
    fs::remove(file);
}

}  // namespace
}  // namespace sbsim::test
