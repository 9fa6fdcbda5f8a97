#include "sbsim/app/inputs/ProjData.h"

#include <link.h>

#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace sbsim::app {

namespace {

/// The folder of the loaded libsumocpp.so, if it is loaded.
std::optional<std::filesystem::path> libsumoFolder() {
    std::optional<std::filesystem::path> found;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* out) {
            const std::string_view name = info->dlpi_name != nullptr ? info->dlpi_name : "";
            if (name.find("libsumocpp") == std::string_view::npos) return 0;
            *static_cast<std::optional<std::filesystem::path>*>(out) = std::filesystem::path(name).parent_path();
            return 1;
        },
        &found);
    return found;
}

}  // namespace

std::optional<std::filesystem::path> pointProjAtSumoData() {
    if (std::getenv("PROJ_DATA") != nullptr || std::getenv("PROJ_LIB") != nullptr) return std::nullopt;
    std::vector<std::filesystem::path> candidates;
    if (const char* home = std::getenv("SUMO_HOME"); home != nullptr && *home != '\0') {
        candidates.push_back(std::filesystem::path(home) / "data" / "proj");
    }
    // The wheel's layout: <SUMO_HOME>/lib64/libsumocpp.so and <SUMO_HOME>/data/proj.
    if (const auto lib = libsumoFolder()) candidates.push_back(lib->parent_path() / "data" / "proj");
    for (const std::filesystem::path& folder : candidates) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(folder / "proj.db", ec)) continue;
        const std::string text = folder.string();
        setenv("PROJ_DATA", text.c_str(), 0);
        setenv("PROJ_LIB", text.c_str(), 0);
        return folder;
    }
    return std::nullopt;
}

}  // namespace sbsim::app
