#include "sbsim/app/run/CheckCommand.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/cli/CommandLine.h"
#include "sbsim/app/inputs/BundledScenario.h"
#include "sbsim/app/inputs/FileLedger.h"
#include "sbsim/app/inputs/ScenarioInputs.h"
#include "sbsim/app/inputs/SumoOptions.h"
#include "sbsim/app/run/NetworkQuestions.h"
#include "sbsim/app/run/Scenario.h"
#include "sbsim/storyboard/StoryAreas.h"
#include "sbsim/storyboard/StoryCheck.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::app {

namespace fs = std::filesystem;

void CheckCommand::declareOptions(CLI::App& command) {
    command.add_flag("--strict", strict_, "exit 1 when there are warnings");
    command.add_flag("--json", json_, "print the stories and warnings as one JSON document");
}

int CheckCommand::run(const CommandLine& cl) {
    const auto [sumocfg, story] = scenarioFiles(cl, true);
    if (!story) throw UsageError("check: --story is required with --sumocfg");
    FileLedger files;
    checkSumoInputs(sumocfg, cl.sumoOptions, files);
    files.requireInput("--story", *story);

    traffic::SumoSettings settings = Scenario::sumoSettings(cl, sumocfg);
    settings.quiet = true;  // the check's own output only
    Scenario scenario(cl, settings, 1);
    scenario.loadSumo();
    scenario.addStoryboard(*story, nullptr).createStories();
    const storyboard::Storyboard& board = *scenario.board();
    const traffic::SumoBridge& sumo = scenario.sumo();

    const NetworkQuestions network(RouteIds(SumoOptions(sumocfg, cl.sumoOptions).files("route-files")));
    storyboard::CheckScenario checked;
    checked.boundary = sumo.netBoundary();
    checked.begin = sumo.beginTime();
    checked.end = sumo.endTime();
    checked.vehicleDefined = [&](std::string_view id) { return network.routes().defines(id); };
    network.answer(checked);
    const auto warnings = storyboard::checkStories(board.stories(), checked);
    const auto criterionWarnings = storyboard::checkCriteria(board.criteria(), checked);
    const std::size_t warningCount = warnings.size() + criterionWarnings.size();

    if (json_) {
        nlohmann::ordered_json out;
        out["story_file"] = story->string();
        out["sumocfg"] = sumocfg.string();
        out["stories"] = nlohmann::ordered_json::array();
        for (const auto& s : board.stories()) {
            nlohmann::ordered_json nodes = nlohmann::ordered_json::array();
            for (const auto& node : storyboard::describeStory(*s))
                nodes.push_back({{"depth", node.depth}, {"text", node.text}});
            // Areas in SUMO's frame, whatever frame the script wrote them in: what the report's map draws.
            nlohmann::ordered_json areas = nlohmann::ordered_json::array();
            for (const auto& area : storyboard::storyAreas(*s)) {
                nlohmann::ordered_json points = nlohmann::ordered_json::array();
                for (const auto& p : area.points) points.push_back({p.x(), p.y()});
                nlohmann::ordered_json entry{{"condition", area.condition->typeName()}, {"points", std::move(points)}};
                if (area.radius) entry["radius"] = *area.radius;
                areas.push_back(std::move(entry));
            }
            const bool world = s->isWorldStory();
            out["stories"].push_back(
                {{"name", s->name()}, {"world", world}, {"tree", std::move(nodes)}, {"areas", std::move(areas)}});
        }
        out["criteria"] = nlohmann::ordered_json::array();
        for (const auto& c : board.criteria()) out["criteria"].push_back(c->name());
        out["warnings"] = nlohmann::ordered_json::array();
        for (const auto& w : warnings) out["warnings"].push_back({{"story", w.story}, {"message", w.message}});
        for (const auto& w : criterionWarnings) {
            out["warnings"].push_back({{"criterion", w.story}, {"message", w.message}});
        }
        fmt::print("{}\n", out.dump(2));
    } else {
        fmt::print("{}: {} stor{} on {}\n", story->string(), board.stories().size(),
                   board.stories().size() == 1 ? "y" : "ies", sumocfg.string());
        for (const auto& s : board.stories()) {
            fmt::print("story '{}'\n", s->name());
            for (const auto& node : storyboard::describeStory(*s)) {
                fmt::print("{}{}\n", std::string(static_cast<std::size_t>(node.depth) * 2, ' '), node.text);
            }
        }
        for (const auto& c : board.criteria()) fmt::print("criterion '{}'\n", c->name());
        for (const auto& w : warnings) fmt::print(stderr, "sbsim: warning: story '{}': {}\n", w.story, w.message);
        for (const auto& w : criterionWarnings) {
            fmt::print(stderr, "sbsim: warning: criterion '{}': {}\n", w.story, w.message);
        }
        fmt::print("{} warning{}\n", warningCount, warningCount == 1 ? "" : "s");
    }
    return strict_ && warningCount != 0 ? 1 : 0;
}

}  // namespace sbsim::app
