#pragma once

#include <filesystem>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::test {

/// The generated test scenario (a 4x4 grid, 120 s, one departure per second), in the folder that
/// ctest passes as SBSIM_TEST_SCENARIOS; fails the test if it is missing.
std::filesystem::path scenarioConfig();
/// A dense one: 2000 vehicles inserted over the first 100 s, ending at 110 s.
std::filesystem::path denseScenarioConfig();

/// Settings for the scenario with a fixed seed.
traffic::SumoSettings scenarioSettings();

inline kernel::SimTime sec(double s) { return kernel::SimTime::fromSeconds(s); }

}  // namespace sbsim::test
