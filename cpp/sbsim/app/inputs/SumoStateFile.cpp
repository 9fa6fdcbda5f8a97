#include "sbsim/app/inputs/SumoStateFile.h"

#include <fmt/format.h>
#include <tinyxml2.h>
#include <zlib.h>

#include <cmath>
#include <memory>
#include <optional>
#include <set>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/inputs/FileLedger.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {

/// The file's text, gunzipped if it is compressed (zlib reads plain files as they are); none if
/// it cannot be read.
std::optional<std::string> readMaybeGzipped(const fs::path& path) {
    const std::unique_ptr<gzFile_s, int (*)(gzFile)> file(gzopen(path.c_str(), "rb"), gzclose);
    if (!file) return std::nullopt;
    std::string text;
    char buffer[1 << 16];
    for (int n; (n = gzread(file.get(), buffer, sizeof buffer)) != 0;) {
        if (n < 0) return std::nullopt;
        text.append(buffer, static_cast<std::size_t>(n));
    }
    return text;
}

struct Network {
    std::set<std::string> edges;
    std::set<std::string> lanes;
};

/// The edges and lanes of the network files; none if one cannot be read.
std::optional<Network> readNetwork(const std::vector<fs::path>& netFiles) {
    if (netFiles.empty()) return std::nullopt;
    Network net;
    for (const fs::path& path : netFiles) {
        const std::optional<std::string> text = readMaybeGzipped(path);
        tinyxml2::XMLDocument doc;
        if (!text || doc.Parse(text->data(), text->size()) != tinyxml2::XML_SUCCESS) return std::nullopt;
        const tinyxml2::XMLElement* root = doc.RootElement();
        if (root == nullptr) return std::nullopt;
        for (const auto* edge = root->FirstChildElement("edge"); edge; edge = edge->NextSiblingElement("edge")) {
            if (const char* id = edge->Attribute("id")) net.edges.insert(id);
            for (const auto* lane = edge->FirstChildElement("lane"); lane; lane = lane->NextSiblingElement("lane")) {
                if (const char* id = lane->Attribute("id")) net.lanes.insert(id);
            }
        }
    }
    return net;
}

}  // namespace

void checkSumoState(const std::string& source, const fs::path& state, const std::vector<fs::path>& netFiles) {
    requireReadableFile(source, state);
    const std::string name = state.string();
    const std::optional<std::string> text = readMaybeGzipped(state);
    if (!text) throw InputError(fmt::format("{}: cannot read '{}' (a damaged gzip file?)", source, name));
    tinyxml2::XMLDocument doc;
    if (doc.Parse(text->data(), text->size()) != tinyxml2::XML_SUCCESS) {
        throw InputError(fmt::format("{}: {}:{}: not a SUMO state: not well-formed XML ({})", source, name,
                                     doc.ErrorLineNum(), tinyxml2::XMLDocument::ErrorIDToName(doc.ErrorID())));
    }
    const tinyxml2::XMLElement* root = doc.RootElement();
    if (root == nullptr || std::string_view(root->Name()) != "snapshot") {
        throw InputError(fmt::format("{}: {}: not a SUMO state: the root element is <{}>, not <snapshot>", source, name,
                                     root == nullptr ? "" : root->Name()));
    }
    double time = NAN;
    if (root->QueryDoubleAttribute("time", &time) != tinyxml2::XML_SUCCESS || !std::isfinite(time) ||
        std::fabs(time) > traffic::SumoBridge::kMaxSeconds) {
        throw InputError(fmt::format("{}: {}:{}: <snapshot> needs a time in seconds (at most {:g})", source, name,
                                     root->GetLineNum(), traffic::SumoBridge::kMaxSeconds));
    }
    const std::optional<Network> net = readNetwork(netFiles);
    if (!net) return;
    for (const auto* element = root->FirstChildElement(); element; element = element->NextSiblingElement()) {
        const std::string_view kind = element->Name();
        if (kind != "lane" && kind != "edge") continue;
        const char* id = element->Attribute("id");
        const std::set<std::string>& known = kind == "lane" ? net->lanes : net->edges;
        if (id != nullptr && known.count(id) != 0) continue;
        throw InputError(fmt::format("{}: {}:{}: {} '{}' is not in the network", source, name, element->GetLineNum(),
                                     kind, id == nullptr ? "" : id));
    }
}

}  // namespace sbsim::app
