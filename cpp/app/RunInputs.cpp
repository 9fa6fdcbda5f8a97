#include "sbsim/app/RunInputs.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>
#include <optional>

#include "sbsim/app/BadInput.h"
#include "sbsim/services/ServiceRegistry.h"

namespace sbsim::app {

namespace fs = std::filesystem;

void requireReadableFile(const std::string& option, const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(fmt::format("{}: no such file '{}'", option, path.string()));
    if (fs::is_directory(path, ec)) {
        throw InputError(fmt::format("{}: '{}' is a directory, not a file", option, path.string()));
    }
    if (std::ifstream(path).fail()) throw InputError(fmt::format("{}: cannot read '{}'", option, path.string()));
}

std::vector<std::unique_ptr<PluginLibrary>> loadPlugins(const std::vector<fs::path>& paths) {
    std::vector<std::unique_ptr<PluginLibrary>> plugins;
    for (const fs::path& plugin : paths) {
        requireReadableFile("--plugin", plugin);
        try {
            plugins.push_back(std::make_unique<PluginLibrary>(plugin));
        } catch (const std::exception& e) {
            throw InputError(fmt::format("--plugin: cannot load '{}': {}", plugin.string(), e.what()));
        }
        if (const auto name = services::ServiceRegistry::instance().takeConflict()) {
            throw InputError(fmt::format("--plugin: '{}' registers service type '{}', which is already registered",
                                         plugin.string(), *name));
        }
    }
    return plugins;
}

services::ServicesConfig loadServicesConfig(const fs::path& path) {
    requireReadableFile("--services", path);
    std::optional<services::ServicesConfig> config;
    try {
        config = services::ServicesConfig::load(path);
    } catch (const std::exception& e) {
        throw InputError(fmt::format("--services: {}", e.what()));
    }
    const services::ServiceRegistry& registry = services::ServiceRegistry::instance();
    for (const services::ServiceSpec& spec : config->services()) {
        if (registry.contains(spec.type)) continue;
        throw InputError(fmt::format("--services: {}:{}: unknown service type '{}' (known: {})", path.string(),
                                     spec.line, spec.type, fmt::join(registry.names(), ", ")));
    }
    return std::move(*config);
}

}  // namespace sbsim::app
