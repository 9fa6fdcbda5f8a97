#include "sbsim/app/run/RadioSetup.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/cli/CommandLine.h"
#include "sbsim/radio/channel/ChannelMedium.h"
#include "sbsim/radio/channel/RadioFile.h"
#include "sbsim/radio/disc/DiscMedium.h"
#include "sbsim/radio/propagation/Obstacles.h"
#include "sbsim/traffic/SumoPolygons.h"

namespace sbsim::app {

namespace {

/// The radio file through the radio's reader; its refusals become the program's bad input.
radio::ChannelSettings readRadioSettings(const std::optional<std::filesystem::path>& file,
                                         const kernel::StudyParameters& parameters) {
    try {
        return radio::readRadioFile(file, parameters);
    } catch (const radio::RadioFileError& e) {
        if (e.fromParameter()) throw UsageError(e.what());
        throw InputError(e.what());
    }
}

}  // namespace

radio::Medium& makeMedium(const CommandLine& cl, kernel::Simulation& sim, const traffic::VehicleSnapshot& snapshot,
                          radio::Medium::Directory directory, std::optional<ObstacleFigures>* obstacleFigures) {
    if (!cl.radio) {
        radio::DiscSettings disc;
        disc.range = cl.v2xRange;
        disc.latency = kernel::SimTime::fromSeconds(cl.v2xLatency);
        disc.fadeStart = cl.v2xFadeStart;
        if (cl.messagesRange) disc.traceRange = *cl.messagesRange;
        // No lost lines asked for: the disc visits no station beyond its range for the trace.
        if (!cl.messagesLost()) disc.traceRange = 0;
        return sim.emplaceModule<radio::DiscMedium>(disc, snapshot, std::move(directory));
    }
    radio::ChannelSettings settings = readRadioSettings(cl.radio, sim.parameters());
    if (cl.messagesRange) settings.traceRange = *cl.messagesRange;
    if (!cl.messagesLost()) settings.traceRange = 0;
    auto obstacles = std::make_shared<radio::Obstacles>(settings.wallDb, settings.perMetreDb);
    std::set<std::string> types;
    for (traffic::SumoPolygons::Polygon& p : traffic::SumoPolygons::all()) {
        if (p.type == settings.obstacleType) obstacles->add(std::move(p.shape));
        types.insert(std::move(p.type));
    }
    if (!types.empty() && types.count(settings.obstacleType) == 0) {
        throw InputError(
            fmt::format("{}: [obstacles] polygon_type '{}' matches no polygon of the scenario (its "
                        "polygon types: {})",
                        cl.radio->string(), settings.obstacleType, fmt::join(types, ", ")));
    }
    if (obstacleFigures != nullptr)
        *obstacleFigures = ObstacleFigures{settings.obstacleType, obstacles->size(), obstacles};
    return sim.emplaceModule<radio::ChannelMedium>(std::move(settings), snapshot, std::move(directory),
                                                   std::move(obstacles));
}

}  // namespace sbsim::app
