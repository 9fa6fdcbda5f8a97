#include "sbsim/radio/channel/RadioFile.h"

#include <fmt/format.h>

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "sbsim/radio/propagation/PathLossModels.h"

namespace sbsim::radio {

namespace {

using Settings = ChannelSettings;

/// A numeric key of the radio file: its section, its kind and closed range (README, Radio, lists
/// the same), and what it sets. A whole key takes no fraction: it is not truncated.
struct NumberKey {
    const char* section;
    bool whole;
    double min;
    double max;
    std::function<void(Settings&, double)> set;

    /// `value` if it is of the key's kind and in its range; else std::invalid_argument saying what it must be.
    double check(double value) const {
        if (!(value >= min && value <= max) || (whole && value != std::floor(value))) {
            throw std::invalid_argument(fmt::format("must be {} from {:g} to {:g}, got {:g}",
                                                    whole ? "a whole number" : "a number", min, max, value));
        }
        return value;
    }
};

/// A text key: the section and what it sets (throws std::invalid_argument for an unknown value).
struct TextKey {
    const char* section;
    std::function<void(Settings&, const std::string&)> set;
};

/// Ranges shared by several keys: levels in dBm, losses in dB, distances in m, times in s.
constexpr double kMaxDbm = 100, kMinDbm = -300;
constexpr double kMaxDb = 1000;
constexpr double kMaxMetres = 1e7;
constexpr double kMaxDelay = 1e3;

NumberKey real(const char* section, double min, double max, std::function<void(Settings&, double)> set) {
    return {section, false, min, max, std::move(set)};
}
NumberKey whole(const char* section, double min, double max, std::function<void(Settings&, double)> set) {
    return {section, true, min, max, std::move(set)};
}

std::map<std::string, NumberKey, std::less<>> makeNumberKeys() {
    std::map<std::string, NumberKey, std::less<>> keys{
        {"power_dbm", real("phy", kMinDbm, kMaxDbm, [](Settings& s, double v) { s.powerDbm = v; })},
        {"rate_mbps", real("phy", 3, 27, [](Settings& s, double v) { s.rateMbps = v; })},
        {"frequency_hz", real("phy", 1e6, 1e12, [](Settings& s, double v) { s.frequencyHz = v; })},
        {"bandwidth_hz", real("phy", 1e3, 1e10, [](Settings& s, double v) { s.bandwidthHz = v; })},
        {"noise_dbm", real("phy", kMinDbm, kMaxDbm, [](Settings& s, double v) { s.noiseDbm = v; })},
        {"sensing_dbm", real("phy", kMinDbm, kMaxDbm, [](Settings& s, double v) { s.sensingDbm = v; })},
        {"interference_floor_dbm",
         real("phy", kMinDbm, kMaxDbm, [](Settings& s, double v) { s.interferenceFloorDbm = v; })},
        {"shadowing_sigma_db", real("propagation", 0, 100, [](Settings& s, double v) { s.shadowingSigmaDb = v; })},
        {"shadowing_correlation_m",
         real("propagation", 0, kMaxMetres, [](Settings& s, double v) { s.shadowingCorrelation = v; })},
        {"nakagami_m", real("propagation", 0.5, 1e3, [](Settings& s, double v) { s.nakagamiM = v; })},
        {"wall_db", real("obstacles", 0, kMaxDb, [](Settings& s, double v) { s.wallDb = v; })},
        {"per_metre_db", real("obstacles", 0, kMaxDb, [](Settings& s, double v) { s.perMetreDb = v; })},
        {"aifsn", whole("mac", 1, 15, [](Settings& s, double v) { s.aifsn = static_cast<int>(v); })},
        {"contention_window",
         whole("mac", 0, 1023, [](Settings& s, double v) { s.contentionWindow = static_cast<int>(v); })},
        {"queue_limit",
         whole("mac", 1, 1e6, [](Settings& s, double v) { s.queueLimit = static_cast<std::size_t>(v); })},
        {"trace_range", real("trace", 0, kMaxMetres, [](Settings& s, double v) { s.traceRange = v; })},
        {"delay_s", real("latency", 0, kMaxDelay, [](Settings& s, double v) { s.delay = v; })},
        {"delay_min_s", real("latency", 0, kMaxDelay, [](Settings& s, double v) { s.delayMin = v; })},
        {"delay_max_s", real("latency", 0, kMaxDelay, [](Settings& s, double v) { s.delayMax = v; })},
        {"delay_shape", real("latency", 1e-3, 1e6, [](Settings& s, double v) { s.delayShape = v; })},
        {"tier_margin_db", real("performance", 0, 100, [](Settings& s, double v) { s.tierMarginDb = v; })},
        {"far_cell_m", real("performance", 0, 1000, [](Settings& s, double v) { s.farCellM = v; })},
        {"links_per_chunk",
         whole("performance", 1, 1e9, [](Settings& s, double v) { s.linksPerChunk = static_cast<std::size_t>(v); })},
    };
    // Each path-loss model's own keys, as its registration declares them: finite here, the
    // model's factory refuses what its law cannot take.
    for (const std::string& key : PathLossModels::keys()) {
        keys.emplace(key, real("propagation", -1e9, 1e9, [key](Settings& s, double v) { s.pathLossKeys[key] = v; }));
    }
    return keys;
}

/// A TOML number as a double, an integer too (toml++'s value<double>() is empty for an integer
/// a double cannot hold exactly); std::invalid_argument for anything else.
double numberOf(const toml::node& node) {
    if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
    if (const auto* d = node.as_floating_point()) return d->get();
    throw std::invalid_argument("must be a number");
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
        const double ebN0 = numberOf((*pair)[0]), fer = numberOf((*pair)[1]);
        if (!std::isfinite(ebN0) || !(fer >= 0 && fer <= 1))
            throw RadioFileError(fmt::format("{}: [fer] table: each row is [Eb/N0 dB, FER], FER from 0 to 1", where),
                                 false);
        points.emplace_back(ebN0, fer);
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
                    n->second.set(s, n->second.check(numberOf(node)));
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
        double number = 0;
        if (const auto* i = std::get_if<std::int64_t>(&*value)) {
            number = static_cast<double>(*i);
        } else if (const auto* d = std::get_if<double>(&*value)) {
            number = *d;
        } else {
            throw RadioFileError(fmt::format("--param radio_{}: must be a number", key), true);
        }
        try {
            entry.set(s, entry.check(number));
        } catch (const std::invalid_argument& e) {
            throw RadioFileError(fmt::format("--param radio_{}: {}", key, e.what()), true);
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
