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
#include "sbsim/app/run/RadioSetup.h"
#include "sbsim/app/run/Scenario.h"
#include "sbsim/services/ServiceError.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/storyboard/StoryAreas.h"
#include "sbsim/storyboard/StoryCheck.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::app {

namespace fs = std::filesystem;

void CheckCommand::declareOptions(CLI::App& command) {
    command.add_flag("--strict", strict_, "exit 1 when there are warnings");
    command.add_flag("--json", json_, "print the stories and warnings as one JSON document");
}

int CheckCommand::run(const CommandLine& cl) {
    const auto [sumocfg, story] = scenarioFiles(cl, true);
    if (!story && !cl.services) throw UsageError("check: --story or --services is required with --sumocfg");
    // The run's own input checks, in the run's order, with its messages: plugins, the services
    // file (every element, filter, attribute, use-case file, roadside unit), the radio file.
    FileLedger files;
    checkSumoInputs(sumocfg, cl.sumoOptions, files);
    if (story) files.requireInput("--story", *story);
    const std::vector<std::unique_ptr<PluginLibrary>> plugins = loadPlugins(cl.plugins, files);
    std::optional<services::ServicesConfig> servicesConfig;
    if (cl.services) servicesConfig = loadServicesConfig(*cl.services, files);
    checkRadioInput(cl, files);

    traffic::SumoSettings settings = Scenario::sumoSettings(cl, sumocfg);
    settings.quiet = true;  // the check's own output only
    Scenario scenario(cl, settings, 1);
    scenario.loadSumo();
    if (story) scenario.addStoryboard(*story, nullptr).createStories();
    const traffic::SumoBridge& sumo = scenario.sumo();
    std::size_t services = 0, roadsideUnits = 0;
    if (servicesConfig) {
        services = servicesConfig->services().size();
        const traffic::Penetration penetration(cl.penetration, scenario.simulation().seed());
        try {
            // As a run sets up: the medium (the radio file read, its buildings found), then what
            // happens before the first event: roadside units placed, their services initialized.
            scenario.addServices(std::move(*servicesConfig), kernel::SimTime::fromSeconds(cl.middlewareInterval),
                                 penetration, nullptr);
            scenario.simulation().initialize();
        } catch (const services::ServiceError& e) {
            throw InputError(e.what());
        } catch (const services::ServicesConfigError& e) {
            throw InputError(fmt::format("--services: {}", e.what()));
        }
        roadsideUnits = scenario.services()->roadsideUnits();
    }

    const NetworkQuestions network(RouteIds(SumoOptions(sumocfg, cl.sumoOptions).files("route-files")));
    storyboard::CheckScenario checked;
    checked.boundary = sumo.netBoundary();
    checked.begin = sumo.beginTime();
    checked.end = sumo.endTime();
    checked.vehicleDefined = [&](std::string_view id) { return network.routes().defines(id); };
    network.answer(checked);
    static const std::vector<storyboard::StoryPtr> noStories;
    static const std::vector<storyboard::CriterionPtr> noCriteria;
    const storyboard::Storyboard* board = scenario.board();
    const auto& stories = board != nullptr ? board->stories() : noStories;
    const auto& criteria = board != nullptr ? board->criteria() : noCriteria;
    const auto warnings = storyboard::checkStories(stories, checked);
    const auto criterionWarnings = storyboard::checkCriteria(criteria, checked);
    const std::size_t warningCount = warnings.size() + criterionWarnings.size();
    const std::optional<ObstacleFigures>& obstacles = scenario.obstacles();

    if (json_) {
        nlohmann::ordered_json out;
        if (story) out["story_file"] = story->string();
        out["sumocfg"] = sumocfg.string();
        out["stories"] = nlohmann::ordered_json::array();
        for (const auto& s : stories) {
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
        for (const auto& c : criteria) out["criteria"].push_back(c->name());
        if (cl.services) {
            out["services"] = {
                {"file", cl.services->string()}, {"services", services}, {"roadside_units", roadsideUnits}};
        }
        if (cl.radio) {
            out["radio"] = {{"file", cl.radio->string()},
                            {"polygon_type", obstacles ? obstacles->polygonType : ""},
                            {"obstacles", obstacles ? obstacles->count : 0}};
        }
        out["warnings"] = nlohmann::ordered_json::array();
        for (const auto& w : warnings) out["warnings"].push_back({{"story", w.story}, {"message", w.message}});
        for (const auto& w : criterionWarnings) {
            out["warnings"].push_back({{"criterion", w.story}, {"message", w.message}});
        }
        fmt::print("{}\n", out.dump(2));
    } else {
        if (story) {
            fmt::print("{}: {} stor{} on {}\n", story->string(), stories.size(), stories.size() == 1 ? "y" : "ies",
                       sumocfg.string());
        }
        for (const auto& s : stories) {
            fmt::print("story '{}'\n", s->name());
            for (const auto& node : storyboard::describeStory(*s)) {
                fmt::print("{}{}\n", std::string(static_cast<std::size_t>(node.depth) * 2, ' '), node.text);
            }
        }
        for (const auto& c : criteria) fmt::print("criterion '{}'\n", c->name());
        if (cl.services) {
            fmt::print("{}: {} service{}, {} roadside unit{}\n", cl.services->string(), services,
                       services == 1 ? "" : "s", roadsideUnits, roadsideUnits == 1 ? "" : "s");
        }
        if (obstacles) {
            fmt::print("{}: {} obstacles (polygon type '{}')\n", cl.radio->string(), obstacles->count,
                       obstacles->polygonType);
        }
        for (const auto& w : warnings) fmt::print(stderr, "sbsim: warning: story '{}': {}\n", w.story, w.message);
        for (const auto& w : criterionWarnings) {
            fmt::print(stderr, "sbsim: warning: criterion '{}': {}\n", w.story, w.message);
        }
        fmt::print("{} warning{}\n", warningCount, warningCount == 1 ? "" : "s");
    }
    return strict_ && warningCount != 0 ? 1 : 0;
}

}  // namespace sbsim::app
