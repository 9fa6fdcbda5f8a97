// NoRedLightRunning on the generated grid (traffic lights at every inner junction), with SUMO
// answering through SumoQueries: drivers obeying the lights pass, drivers told to ignore red (a
// speed mode without bit 4) fail it, and in both runs the criterion's count of red passages
// equals what SUMO's own next-signal list (getNextTLS) shows, an independent way to see them.
#include <gtest/gtest.h>
#include <libsumo/Simulation.h>
#include <libsumo/TraCIDefs.h>
#include <libsumo/TrafficLight.h>
#include <libsumo/Vehicle.h>

#include <map>
#include <optional>
#include <string>
#include <utility>

#include "SumoTestSupport.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/storyboard/EvaluationContext.h"
#include "sbsim/storyboard/criteria/NoRedLightRunning.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/SumoBridge.h"
#include "sbsim/traffic/TrafficQueries.h"

namespace sbsim::test {
namespace {

using storyboard::CriterionVerdict;
using storyboard::NoRedLightRunning;

struct GridRun {
    CriterionVerdict verdict;
    std::map<char, int> passedBySumo;  // passages by the link's state, from getNextTLS
};

/// Runs the grid to its end (120 s) with every departing vehicle in `speedMode`, the criterion watching.
GridRun runGrid(int speedMode) {
    kernel::Simulation sim;
    auto& bridge = sim.emplaceModule<traffic::SumoBridge>(scenarioSettings());
    bridge.demandColumns(traffic::SnapshotColumns::Lane);
    bridge.load();
    sim.initialize();
    traffic::SumoQueries queries;
    traffic::NeighbourGrid grid;
    NoRedLightRunning criterion{storyboard::VehicleSet{}};
    GridRun out;
    std::map<std::string, std::pair<std::string, int>> nextSignal;  // per vehicle, after the last step
    for (kernel::SimTime t = bridge.stepLength(); t < sec(120); t += bridge.stepLength()) {
        EXPECT_EQ(sim.run(t), kernel::Simulation::StopReason::TimeLimit);
        for (const std::string& id : libsumo::Simulation::getDepartedIDList()) {
            libsumo::Vehicle::setSpeedMode(id, speedMode);
        }
        const traffic::VehicleSnapshot& snapshot = bridge.snapshot();
        grid.build(snapshot, 100);
        criterion.prepare(storyboard::EvaluationContext(snapshot, grid, &queries));
        // The oracle: a vehicle whose first upcoming signal link changed passed that link's line.
        std::map<std::string, std::pair<std::string, int>> now;
        for (const std::string& id : snapshot.ids()) {
            const auto next = libsumo::Vehicle::getNextTLS(id);
            if (!next.empty()) now[id] = {next.front().id, next.front().tlIndex};
            const auto before = nextSignal.find(id);
            if (before == nextSignal.end() || (now.contains(id) && now[id] == before->second)) continue;
            const auto& [signal, index] = before->second;
            ++out.passedBySumo[libsumo::TrafficLight::getRedYellowGreenState(signal).at(index)];
        }
        nextSignal = std::move(now);
    }
    out.verdict = criterion.verdict(storyboard::CriterionRun{{}, nullptr, {}});
    sim.finish();
    return out;
}

int redPassages(const std::map<char, int>& byState) {
    int n = 0;
    for (const auto& [state, count] : byState) n += NoRedLightRunning::isRed(state) ? count : 0;
    return n;
}

TEST(RedLightRunning, DriversObeyingTheLightsPassIt) {
    const GridRun run = runGrid(31);  // SUMO's default: brake hard for red
    EXPECT_TRUE(run.verdict.passed) << run.verdict.actual;
    EXPECT_EQ(run.verdict.actual, "0 red-light passages");
    EXPECT_EQ(redPassages(run.passedBySumo), 0);
    // Not vacuous: vehicles did pass the grid's lights, on green (and yellow).
    EXPECT_GT(run.passedBySumo.at('G'), 50);
}

TEST(RedLightRunning, DriversIgnoringRedFailItCountedAsSumoShows) {
    const GridRun run = runGrid(15);  // bit 4 off: SUMO lets them drive through red
    EXPECT_FALSE(run.verdict.passed);
    const int red = redPassages(run.passedBySumo);
    EXPECT_GT(red, 20);
    EXPECT_EQ(run.verdict.actual.substr(0, run.verdict.actual.find(" red-light")), std::to_string(red))
        << run.verdict.actual;
    EXPECT_EQ(run.verdict.expected, "0 red-light passages");
    std::cout << "red-light passages: " << run.verdict.actual << "\n";
}

}  // namespace
}  // namespace sbsim::test
