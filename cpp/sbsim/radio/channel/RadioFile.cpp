#include "sbsim/radio/channel/RadioFile.h"

#include <fmt/format.h>

#include <toml++/toml.h>
#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "sbsim/radio/propagation/PathLossModels.h"

namespace sbsim::radio {

namespace {

using Settings = ChannelSettings;

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

std::map<std::string, NumberKey, std::less<>> makeNumberKeys() {
    std::map<std::string, NumberKey, std::less<>> keys{
        {"power_dbm", {"phy", [](Settings& s, double v) { s.powerDbm = v; }}},
        {"rate_mbps", {"phy", [](Settings& s, double v) { s.rateMbps = v; }}},
        {"frequency_hz", {"phy", [](Settings& s, double v) { s.frequencyHz = v; }}},
        {"bandwidth_hz", {"phy", [](Settings& s, double v) { s.bandwidthHz = v; }}},
        {"noise_dbm", {"phy", [](Settings& s, double v) { s.noiseDbm = v; }}},
        {"sensing_dbm", {"phy", [](Settings& s, double v) { s.sensingDbm = v; }}},
        {"interference_floor_dbm", {"phy", [](Settings& s, double v) { s.interferenceFloorDbm = v; }}},
        {"shadowing_sigma_db", {"propagation", [](Settings& s, double v) { s.shadowingSigmaDb = v; }}},
        {"shadowing_correlation_m", {"propagation", [](Settings& s, double v) { s.shadowingCorrelation = v; }}},
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
        {"tier_margin_db", {"performance", [](Settings& s, double v) { s.tierMarginDb = v; }}},
        {"links_per_chunk",
         {"performance", [](Settings& s, double v) { s.linksPerChunk = static_cast<std::size_t>(std::max(v, 0.0)); }}},
    };
    // Each path-loss model's own keys, as its registration declares them.
    for (const std::string& key : PathLossModels::keys()) {
        keys.emplace(key, NumberKey{"propagation", [key](Settings& s, double v) { s.pathLossKeys[key] = v; }});
    }
    return keys;
}

const std::map<std::string, NumberKey, std::less<>>& numberKeys() {
    static const std::map<std::string, NumberKey, std::less<>> keys = makeNumberKeys();
    return keys;
}

const std::map<std::string, TextKey, std::less<>>& textKeys() {
    static const std::map<std::string, TextKey, std::less<>> keys{
        {"path_loss",
         {"propagation",
          [](Settings& s, const std::string& v) {
              if (PathLossModels::all().count(v) == 0)
                  throw std::invalid_argument("must be " + PathLossModels::names());
              s.pathLoss = v;
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
        {"link_budget",
         {"performance",
          [](Settings& s, const std::string& v) {
              if (v != "tiers" && v != "exact") throw std::invalid_argument("must be tiers or exact");
              s.linkTiers = v == "tiers";
          }}},
        {"security",
         {"frame",
          [](Settings& s, const std::string& v) {
              if (v != "signed" && v != "none") throw std::invalid_argument("must be signed or none");
              s.secured = v == "signed";
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
            throw RadioFileError(fmt::format("{}: [fer] table: each row is [Eb/N0 dB, FER]", where), false);
        points.emplace_back((*pair)[0].value<double>().value(), (*pair)[1].value<double>().value());
    }
    return points;
}

void readFile(const std::filesystem::path& file, Settings& s) {
    const std::string where = file.string();
    toml::table doc;
    try {
        doc = toml::parse_file(where);
    } catch (const toml::parse_error& e) {
        throw RadioFileError(fmt::format("{}:{}: {}", where, e.source().begin.line, e.description()), false);
    }
    for (const auto& [sectionName, sectionNode] : doc) {
        const std::string section(sectionName.str());
        const toml::table* table = sectionNode.as_table();
        if (table == nullptr) throw RadioFileError(fmt::format("{}: '{}' must be a [section]", where, section), false);
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
                } else if (const auto t = textKeys().find(key); t != textKeys().end() && section == t->second.section) {
                    if (!node.is_string()) throw std::invalid_argument("must be a string");
                    t->second.set(s, node.value<std::string>().value());
                } else {
                    throw std::invalid_argument("is not a radio setting (see README, Radio)");
                }
            } catch (const std::invalid_argument& e) {
                throw RadioFileError(fmt::format("{}: {}", at, e.what()), false);
            }
        }
    }
}

}  // namespace

ChannelSettings readRadioFile(const std::optional<std::filesystem::path>& file,
                              const kernel::StudyParameters& parameters) {
    Settings s;
    if (file) readFile(*file, s);
    // Study parameters last: a sweep varies what the file fixes.
    for (const auto& [key, entry] : numberKeys()) {
        const auto value = parameters.get("radio_" + key);
        if (!value) continue;
        if (const auto* i = std::get_if<std::int64_t>(&*value)) {
            entry.set(s, static_cast<double>(*i));
        } else if (const auto* d = std::get_if<double>(&*value)) {
            entry.set(s, *d);
        } else {
            throw RadioFileError(fmt::format("--param radio_{}: must be a number", key), true);
        }
    }
    for (const auto& [key, entry] : textKeys()) {
        const auto value = parameters.get("radio_" + key);
        if (!value) continue;
        try {
            entry.set(s, kernel::StudyParameters::format(*value));
        } catch (const std::invalid_argument& e) {
            throw RadioFileError(fmt::format("--param radio_{}: {}", key, e.what()), true);
        }
    }
    try {
        s.validate();
    } catch (const std::invalid_argument& e) {
        throw RadioFileError(fmt::format("{}: {}", file ? file->string() : std::string("radio settings"), e.what()),
                             false);
    }
    return s;
}

}  // namespace sbsim::radio
