#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <optional>

#include "sbsim/app/outputs/MessageTraceFile.h"

#include "sbsim/app/run/RadioSetup.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/kernel/Statistics.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/traffic/EquippedVehicles.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::app {

/// What the final summary reports on; the modules a run did not have are null.
struct RunFigures {
    const std::filesystem::path& sumocfg;
    const kernel::Simulation& sim;
    const traffic::SumoBridge& sumo;
    const storyboard::Storyboard* board;
    const services::ServiceManager* services;
    const radio::Medium* medium;
    const kernel::Statistics* statistics;  ///< what services and stories recorded
    /// The criteria's verdicts over the run, in registration order (none without criteria).
    const std::vector<std::pair<std::string, storyboard::CriterionVerdict>>& verdicts;
    double wall;                                              ///< s
    const std::vector<std::string>& arguments;                ///< the command line
    std::optional<TraceFigures> messageTrace = std::nullopt;  ///< --messages
    /// The channel model's buildings (--radio); null for the disc model.
    const ObstacleFigures* obstacles = nullptr;
    /// Which vehicles departed V2X-equipped (a run with services); null without services.
    const traffic::EquippedVehicles* equipped = nullptr;
};

/// `key: value` lines on stdout: first what the run did (identical for identical runs), then the
/// timing lines.
void printSummary(const RunFigures& figures);

/// The same figures as one JSON document (--summary), plus what a table of runs needs: active
/// vehicle-seconds per story, SUMO's version, the command line.
nlohmann::ordered_json summaryJson(const RunFigures& figures);

}  // namespace sbsim::app
