#include "sbsim/app/run/RadioSetup.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <toml++/toml.h>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <variant>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/cli/CommandLine.h"
#include "sbsim/radio/ChannelMedium.h"
#include "sbsim/radio/DiscMedium.h"
#include "sbsim/radio/Obstacles.h"
#include "sbsim/traffic/SumoPolygons.h"

namespace sbsim::app {

namespace {

using Settings = radio::ChannelSettings;

/// A numeric key of the radio file: its section and what it sets.
struct NumberKey {
    const char* section;
    std::function<void(Settings&, double)> set;
};
/// A text key: the section and what it sets (throws std::invalid_argument for an unknown value).
struct TextKey {
    const char* section;
    std::function<void(Settings&, const std::string&)> set;
};

const std::map<std::string, NumberKey, std::less<>>& numberKeys() {
    static const std::map<std::string, NumberKey, std::less<>> keys{
        {"power_dbm", {"phy", [](Settings& s, double v) { s.powerDbm = v; }}},
        {"rate_mbps", {"phy", [](Settings& s, double v) { s.rateMbps = v; }}},
        {"frequency_hz", {"phy", [](Settings& s, double v) { s.frequencyHz = v; }}},
        {"bandwidth_hz", {"phy", [](Settings& s, double v) { s.bandwidthHz = v; }}},
        {"noise_dbm", {"phy", [](Settings& s, double v) { s.noiseDbm = v; }}},
        {"sensing_dbm", {"phy", [](Settings& s, double v) { s.sensingDbm = v; }}},
        {"interference_floor_dbm", {"phy", [](Settings& s, double v) { s.interferenceFloorDbm = v; }}},
        {"antenna_height", {"propagation", [](Settings& s, double v) { s.antennaHeight = v; }}},
        {"environment_height", {"propagation", [](Settings& s, double v) { s.environmentHeight = v; }}},
        {"reference_loss_db", {"propagation", [](Settings& s, double v) { s.referenceLossDb = v; }}},
        {"reference_distance", {"propagation", [](Settings& s, double v) { s.referenceDistance = v; }}},
        {"exponent", {"propagation", [](Settings& s, double v) { s.exponent = v; }}},
        {"shadowing_sigma_db", {"propagation", [](Settings& s, double v) { s.shadowingSigmaDb = v; }}},
        {"nakagami_m", {"propagation", [](Settings& s, double v) { s.nakagamiM = v; }}},
        {"wall_db", {"obstacles", [](Settings& s, double v) { s.wallDb = v; }}},
        {"per_metre_db", {"obstacles", [](Settings& s, double v) { s.perMetreDb = v; }}},
        {"aifsn", {"mac", [](Settings& s, double v) { s.aifsn = static_cast<int>(v); }}},
        {"contention_window", {"mac", [](Settings& s, double v) { s.contentionWindow = static_cast<int>(v); }}},
        {"queue_limit",
         {"mac", [](Settings& s, double v) { s.queueLimit = static_cast<std::size_t>(std::max(v, 0.0)); }}},
        {"trace_range", {"trace", [](Settings& s, double v) { s.traceRange = v; }}},
        {"delay_s", {"latency", [](Settings& s, double v) { s.delay = v; }}},
        {"delay_min_s", {"latency", [](Settings& s, double v) { s.delayMin = v; }}},
        {"delay_max_s", {"latency", [](Settings& s, double v) { s.delayMax = v; }}},
        {"delay_shape", {"latency", [](Settings& s, double v) { s.delayShape = v; }}},
        {"links_per_chunk",
         {"performance", [](Settings& s, double v) { s.linksPerChunk = static_cast<std::size_t>(std::max(v, 0.0)); }}},
    };
    return keys;
}

const std::map<std::string, TextKey, std::less<>>& textKeys() {
    static const std::map<std::string, TextKey, std::less<>> keys{
        {"path_loss",
         {"propagation",
          [](Settings& s, const std::string& v) {
              static const std::map<std::string, Settings::PathLossModel, std::less<>> models{
                  {"free-space", Settings::PathLossModel::FreeSpace},
                  {"log-distance", Settings::PathLossModel::LogDistance},
                  {"two-ray-ground", Settings::PathLossModel::TwoRayGround},
                  {"winner-b1", Settings::PathLossModel::WinnerB1}};
              const auto it = models.find(v);
              if (it == models.end())
                  throw std::invalid_argument("must be free-space, log-distance, two-ray-ground or winner-b1");
              s.pathLoss = it->second;
          }}},
        {"fading",
         {"propagation",
          [](Settings& s, const std::string& v) {
              if (v == "none") {
                  s.fading = Settings::Fading::None;
              } else if (v == "nakagami") {
                  s.fading = Settings::Fading::Nakagami;
              } else if (v == "nakagami-veins") {
                  s.fading = Settings::Fading::NakagamiVeins;
              } else {
                  throw std::invalid_argument("must be none, nakagami or nakagami-veins");
              }
          }}},
        {"delay_model",
         {"latency",
          [](Settings& s, const std::string& v) {
              static const std::map<std::string, Settings::ExtraDelay, std::less<>> models{
                  {"none", Settings::ExtraDelay::None},
                  {"constant", Settings::ExtraDelay::Constant},
                  {"uniform", Settings::ExtraDelay::Uniform},
                  {"gamma", Settings::ExtraDelay::Gamma}};
              const auto it = models.find(v);
              if (it == models.end()) throw std::invalid_argument("must be none, constant, uniform or gamma");
              s.extraDelay = it->second;
          }}},
        {"polygon_type", {"obstacles", [](Settings& s, const std::string& v) { s.obstacleType = v; }}},
    };
    return keys;
}

std::vector<std::pair<double, double>> readTable(const toml::array& rows, const std::string& where) {
    std::vector<std::pair<double, double>> points;
    for (const toml::node& row : rows) {
        const toml::array* pair = row.as_array();
        if (pair == nullptr || pair->size() != 2 || !(*pair)[0].is_number() || !(*pair)[1].is_number())
            throw InputError(fmt::format("{}: [fer] table: each row is [Eb/N0 dB, FER]", where));
        points.emplace_back((*pair)[0].value<double>().value(), (*pair)[1].value<double>().value());
    }
    return points;
}

}  // namespace

radio::ChannelSettings readRadioSettings(const std::optional<std::filesystem::path>& file,
                                         const kernel::StudyParameters& parameters) {
    Settings s;
    if (file) {
        const std::string where = file->string();
        toml::table doc;
        try {
            doc = toml::parse_file(where);
        } catch (const toml::parse_error& e) {
            throw InputError(fmt::format("{}:{}: {}", where, e.source().begin.line, e.description()));
        }
        for (const auto& [sectionName, sectionNode] : doc) {
            const std::string section(sectionName.str());
            const toml::table* table = sectionNode.as_table();
            if (table == nullptr) throw InputError(fmt::format("{}: '{}' must be a [section]", where, section));
            for (const auto& [keyName, node] : *table) {
                const std::string key(keyName.str());
                const auto at = fmt::format("{}:{}: [{}] {}", where, node.source().begin.line, section, key);
                try {
                    if (section == "fer" && key == "table") {
                        if (!node.is_array()) throw std::invalid_argument("must be a list of [Eb/N0 dB, FER]");
                        s.ferTable = readTable(*node.as_array(), where);
                    } else if (const auto n = numberKeys().find(key);
                               n != numberKeys().end() && section == n->second.section) {
                        if (!node.is_number()) throw std::invalid_argument("must be a number");
                        n->second.set(s, node.value<double>().value());
                    } else if (const auto t = textKeys().find(key);
                               t != textKeys().end() && section == t->second.section) {
                        if (!node.is_string()) throw std::invalid_argument("must be a string");
                        t->second.set(s, node.value<std::string>().value());
                    } else {
                        throw std::invalid_argument("is not a radio setting (see README, Radio)");
                    }
                } catch (const std::invalid_argument& e) {
                    throw InputError(fmt::format("{}: {}", at, e.what()));
                }
            }
        }
    }
    // Study parameters last: a sweep varies what the file fixes.
    for (const auto& [key, entry] : numberKeys()) {
        const auto value = parameters.get("radio_" + key);
        if (!value) continue;
        if (const auto* i = std::get_if<std::int64_t>(&*value)) {
            entry.set(s, static_cast<double>(*i));
        } else if (const auto* d = std::get_if<double>(&*value)) {
            entry.set(s, *d);
        } else {
            throw UsageError(fmt::format("--param radio_{}: must be a number", key));
        }
    }
    for (const auto& [key, entry] : textKeys()) {
        const auto value = parameters.get("radio_" + key);
        if (!value) continue;
        try {
            entry.set(s, kernel::StudyParameters::format(*value));
        } catch (const std::invalid_argument& e) {
            throw UsageError(fmt::format("--param radio_{}: {}", key, e.what()));
        }
    }
    try {
        s.validate();
    } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("{}: {}", file ? file->string() : std::string("radio settings"), e.what()));
    }
    return s;
}

radio::Medium& makeMedium(const CommandLine& cl, kernel::Simulation& sim, const traffic::VehicleSnapshot& snapshot,
                          radio::Medium::Directory directory, std::optional<ObstacleFigures>* obstacleFigures) {
    if (!cl.radio) {
        radio::DiscSettings disc;
        disc.range = cl.v2xRange;
        disc.latency = kernel::SimTime::fromSeconds(cl.v2xLatency);
        disc.fadeStart = cl.v2xFadeStart;
        if (cl.messagesRange) disc.traceRange = *cl.messagesRange;
        return sim.emplaceModule<radio::DiscMedium>(disc, snapshot, std::move(directory));
    }
    radio::ChannelSettings settings = readRadioSettings(cl.radio, sim.parameters());
    if (cl.messagesRange) settings.traceRange = *cl.messagesRange;
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
    if (obstacleFigures != nullptr) *obstacleFigures = ObstacleFigures{settings.obstacleType, obstacles->size()};
    return sim.emplaceModule<radio::ChannelMedium>(std::move(settings), snapshot, std::move(directory),
                                                   std::move(obstacles));
}

}  // namespace sbsim::app
