#include "SumoTestSupport.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace sbsim::test {

namespace {
std::filesystem::path generated(const std::filesystem::path& relative) {
    const char* dir = std::getenv("SBSIM_TEST_SCENARIOS");
    if (dir == nullptr) {
        ADD_FAILURE() << "SBSIM_TEST_SCENARIOS is not set: run the SUMO tests through ctest";
        return {};
    }
    std::filesystem::path path = std::filesystem::path(dir) / relative;
    if (!std::filesystem::exists(path)) ADD_FAILURE() << path << " is missing: its ctest fixture did not run";
    return path;
}
}  // namespace

std::filesystem::path scenarioConfig() { return generated("grid/grid.sumocfg"); }
std::filesystem::path denseScenarioConfig() { return generated("dense/dense.sumocfg"); }

traffic::SumoSettings scenarioSettings() {
    traffic::SumoSettings settings;
    settings.sumocfg = scenarioConfig();
    settings.seed = 7;
    settings.quiet = true;
    return settings;
}

}  // namespace sbsim::test
