#include "sbsim/app/inputs/SumoOptionTable.h"

#include <tinyxml2.h>

#include <sstream>
#include <stdexcept>

namespace sbsim::app {

/// Generated from `sumo --save-template` by cpp/sbsim/app/CMakeLists.txt.
extern const char* const kSumoOptionTemplate;

namespace {

/// Whether a FILE option is read: SUMO's table has no direction, so its name and section tell.
/// A name with "input" is read wherever it sits (fcd-output.filter-edges.input-file); one with
/// "output" is written (device.rerouting.output); otherwise the output, report (logs) and
/// configuration (save-*) sections hold written files and every other section read ones.
bool isRead(std::string_view name, std::string_view section) {
    if (name.find("input") != std::string_view::npos) return true;
    if (name.find("output") != std::string_view::npos) return false;
    return section != "output" && section != "report" && section != "configuration";
}

}  // namespace

const SumoOptionTable& SumoOptionTable::instance() {
    static const SumoOptionTable table(kSumoOptionTemplate);
    return table;
}

SumoOptionTable::SumoOptionTable(const char* templateXml) {
    tinyxml2::XMLDocument doc;
    if (doc.Parse(templateXml) != tinyxml2::XML_SUCCESS || doc.RootElement() == nullptr) {
        throw std::runtime_error("SUMO's option template does not parse");
    }
    for (const auto* section = doc.RootElement()->FirstChildElement(); section;
         section = section->NextSiblingElement()) {
        for (const auto* option = section->FirstChildElement(); option; option = option->NextSiblingElement()) {
            const std::string name = option->Name();
            const char* type = option->Attribute("type");
            options_[name] = {section->Name(), type != nullptr ? type : ""};
            if (const char* synonyms = option->Attribute("synonymes")) {
                std::istringstream words(synonyms);
                for (std::string word; words >> word;) synonyms_.emplace(word, name);
            }
            const bool file = type != nullptr && std::string_view(type) == "FILE";
            if (file && isRead(name, section->Name())) readFiles_.push_back(name);
        }
    }
}

std::string SumoOptionTable::canonical(std::string_view name) const {
    if (options_.contains(name)) return std::string(name);
    const auto it = synonyms_.find(name);
    return it == synonyms_.end() ? std::string() : it->second;
}

bool SumoOptionTable::isReadFile(std::string_view name) const {
    for (const std::string& option : readFiles_) {
        if (option == name) return true;
    }
    return false;
}

bool SumoOptionTable::isBool(std::string_view name) const {
    const auto it = options_.find(name);
    return it != options_.end() && it->second.type == "BOOL";
}

}  // namespace sbsim::app
