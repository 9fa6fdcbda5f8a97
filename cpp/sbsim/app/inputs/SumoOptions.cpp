#include "sbsim/app/inputs/SumoOptions.h"

#include <fmt/format.h>
#include <tinyxml2.h>

#include <array>
#include <string_view>
#include <utility>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/inputs/FileLedger.h"
#include "sbsim/app/inputs/SumoOptionTable.h"

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {

/// The five input options whose files must be regular files when they exist (a FIFO would block
/// SUMO); other files SUMO reads (lookup tables, replayed traces) are only kept from being
/// overwritten.
bool mustBeRegular(std::string_view name) {
    return name == "net-file" || name == "route-files" || name == "additional-files" || name == "weight-files" ||
           name == "load-state";
}

struct Unrunnable {
    std::string_view name;
    std::string_view why;
};
constexpr std::array<Unrunnable, 7> kUnrunnable{{
    {"remote-port", "it makes SUMO wait for a TraCI client, but sbsim drives SUMO itself"},
    {"num-clients", "it makes SUMO wait for TraCI clients, but sbsim drives SUMO itself"},
    {"help", "it prints SUMO's help and exits; run sumo --help to read it"},
    {"version", "it prints SUMO's version and exits; run sumo --version to read it"},
    {"save-configuration", "it makes SUMO write a configuration and exit instead of running"},
    {"save-template", "it makes SUMO write a configuration template and exit instead of running"},
    {"save-schema", "it makes SUMO write a schema and exit instead of running"},
}};

/// Whether a value turns an option on: SUMO's false booleans, an unset server port and an empty
/// file name leave it off.
bool isOn(std::string_view name, std::string_view value) {
    if (value == "false" || value == "False" || value == "FALSE") return false;
    if (name == "remote-port" || name == "num-clients") return value != "0" && !value.empty();
    return name == "help" || name == "version" || !value.empty();
}

std::string trimmed(std::string_view s) {
    const std::size_t first = s.find_first_not_of(" \t");
    if (first == std::string_view::npos) return {};
    return std::string(s.substr(first, s.find_last_not_of(" \t") - first + 1));
}

}  // namespace

SumoOptions::SumoOptions(const fs::path& sumocfg, const std::vector<std::string>& words) : sumocfg_(sumocfg) {
    readSumocfg();
    readWords(words);
}

void SumoOptions::readSumocfg() {
    tinyxml2::XMLDocument doc;
    if (doc.LoadFile(sumocfg_.c_str()) != tinyxml2::XML_SUCCESS || doc.RootElement() == nullptr) return;
    // Options sit in sections (<input>, <time>, ...) or straight under the root: take any element
    // with a value.
    std::vector<const tinyxml2::XMLElement*> pending{doc.RootElement()};
    while (!pending.empty()) {
        const tinyxml2::XMLElement* element = pending.back();
        pending.pop_back();
        // SUMO takes an element named by any of an option's synonyms (<net value>, <routes value>).
        if (const char* value = element->Attribute("value")) {
            const std::string name = SumoOptionTable::instance().canonical(element->Name());
            if (!name.empty()) settings_[name] = {value, true};
        }
        for (const auto* child = element->FirstChildElement(); child; child = child->NextSiblingElement()) {
            pending.push_back(child);
        }
    }
}

void SumoOptions::readWords(const std::vector<std::string>& words) {
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string_view word = words[i];
        std::string spelled;
        std::optional<std::string> value;
        if (word.starts_with("--") || (word.size() > 1 && word[0] == '-' && !(word[1] >= '0' && word[1] <= '9'))) {
            const std::string_view body = word.substr(word.starts_with("--") ? 2 : 1);
            const std::size_t equals = body.find('=');
            spelled = std::string(body.substr(0, equals));
            if (equals != std::string_view::npos) value = std::string(body.substr(equals + 1));
        }
        // Any spelling SUMO's option table knows: --route-files, --routes, -r.
        const std::string name = spelled.empty() ? std::string() : SumoOptionTable::instance().canonical(spelled);
        if (name.empty()) continue;  // a value, or an option sbsim does not look at
        // A value follows unless the next word is another option (a negative number is a value);
        // a boolean is switched on by its name alone.
        if (!value && i + 1 < words.size()) {
            const std::string& next = words[i + 1];
            const bool isOption = next.size() > 1 && next[0] == '-' && !(next[1] >= '0' && next[1] <= '9');
            const bool isBool = SumoOptionTable::instance().isBool(name);
            if (!isOption && (!isBool || next == "true" || next == "false"))
                value = words[++i];
            else if (isBool)
                value = "true";
        }
        settings_[name] = {value.value_or(""), false};
    }
}

std::string SumoOptions::sourceOf(const std::string& name) const {
    const auto it = settings_.find(name);
    if (it != settings_.end() && it->second.inSumocfg) return fmt::format("the sumocfg '{}'", sumocfg_.string());
    return "the SUMO options";
}

void SumoOptions::rejectUnrunnable() const {
    for (const Unrunnable& option : kUnrunnable) {
        const auto it = settings_.find(std::string(option.name));
        if (it == settings_.end() || !isOn(option.name, it->second.value)) continue;
        const std::string message =
            fmt::format("SUMO option --{} (in {}): {}", option.name, sourceOf(it->first), option.why);
        if (it->second.inSumocfg) throw InputError(message);
        throw UsageError(message);
    }
}

std::vector<fs::path> SumoOptions::files(const std::string& name) const {
    const auto it = settings_.find(name);
    if (it == settings_.end()) return {};
    std::vector<fs::path> out;
    std::string_view rest = it->second.value;
    while (!rest.empty()) {
        const std::size_t comma = rest.find(',');
        const std::string item = trimmed(rest.substr(0, comma));
        rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
        if (item.empty()) continue;
        const fs::path path(item);
        // SUMO reads a sumocfg's relative paths from the sumocfg's folder.
        out.push_back(it->second.inSumocfg && path.is_relative() ? sumocfg_.parent_path() / path : path);
    }
    return out;
}

void SumoOptions::addInputs(FileLedger& files) const {
    for (const std::string& option : SumoOptionTable::instance().readFiles()) {
        for (const fs::path& file : this->files(option)) {
            // A folder some options name (phemlight-path) is SUMO's business; a file is kept safe.
            std::error_code ec;
            if (!mustBeRegular(option) && !fs::is_regular_file(file, ec)) continue;
            files.addReferencedInput(fmt::format("--{} in {}", option, sourceOf(option)), file);
        }
    }
}

}  // namespace sbsim::app
