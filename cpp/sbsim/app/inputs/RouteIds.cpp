#include "sbsim/app/inputs/RouteIds.h"

#include <tinyxml2.h>

namespace sbsim::app {

void RouteIds::read() const {
    if (read_) return;
    read_ = true;
    for (const std::filesystem::path& file : files_) {
        tinyxml2::XMLDocument doc;
        if (doc.LoadFile(file.c_str()) != tinyxml2::XML_SUCCESS || doc.RootElement() == nullptr) continue;
        for (const auto* e = doc.RootElement()->FirstChildElement(); e; e = e->NextSiblingElement()) {
            const char* id = e->Attribute("id");
            if (id == nullptr) continue;
            const std::string_view tag = e->Name();
            if (tag == "vehicle" || tag == "trip") ids_.insert(id);
            if (tag == "flow") flows_.insert(id);
            if (tag == "vType" || tag == "vTypeDistribution") types_.insert(id);
        }
    }
}

bool RouteIds::defines(std::string_view id) const {
    read();
    if (ids_.contains(id)) return true;
    const auto dot = id.rfind('.');
    return dot != std::string_view::npos && flows_.contains(id.substr(0, dot));
}

bool RouteIds::definesType(std::string_view id) const {
    read();
    return types_.contains(id);
}

}  // namespace sbsim::app
