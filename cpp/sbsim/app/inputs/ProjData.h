#pragma once

#include <filesystem>
#include <optional>

namespace sbsim::app {

/// Where PROJ finds proj.db. SUMO converts geo-referenced networks (any OSM import, Artery's
/// Erlangen) with PROJ, and the eclipse-sumo wheel ships proj.db under $SUMO_HOME/data/proj, but
/// nothing tells PROJ so: every such run printed "pj_obj_create: Cannot find proj.db". Unless the
/// user set PROJ_DATA or PROJ_LIB (older PROJ), point both at SUMO's copy: $SUMO_HOME's if set,
/// else the one beside the loaded libsumocpp.so. Returns the folder chosen, if any.
std::optional<std::filesystem::path> pointProjAtSumoData();

}  // namespace sbsim::app
