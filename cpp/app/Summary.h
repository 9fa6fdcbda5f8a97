#pragma once

#include <filesystem>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/services/Medium.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::app {

/// What the final summary reports on; the modules a run did not have are null.
struct RunFigures {
    const std::filesystem::path& sumocfg;
    const kernel::Simulation& sim;
    const traffic::SumoBridge& sumo;
    const storyboard::Storyboard* board;
    const services::ServiceManager* services;
    const services::Medium* medium;
    double wall;  ///< s
};

/// `key: value` lines on stdout: first what the run did (identical for identical runs), then the
/// timing lines.
void printSummary(const RunFigures& figures);

}  // namespace sbsim::app
