#include "sbsim/app/inputs/ScenarioInputs.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>
#include <optional>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/inputs/BundledScenario.h"
#include "sbsim/app/inputs/ElfFile.h"
#include "sbsim/app/inputs/SumoOptions.h"
#include "sbsim/app/inputs/SumoStateFile.h"
#include "sbsim/services/ServiceRegistry.h"

namespace sbsim::app {

namespace fs = std::filesystem;

std::vector<std::unique_ptr<PluginLibrary>> loadPlugins(const std::vector<fs::path>& paths, FileLedger& files) {
    std::vector<std::unique_ptr<PluginLibrary>> plugins;
    services::ServiceRegistry& registry = services::ServiceRegistry::instance();
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const fs::path& plugin = paths[i];
        files.requireInput("--plugin", plugin);
        for (std::size_t j = 0; j < i; ++j) {
            std::error_code ec;
            if (fs::equivalent(plugin, paths[j], ec)) {
                throw UsageError(
                    fmt::format("--plugin: '{}' is given twice (also as '{}')", plugin.string(), paths[j].string()));
            }
        }
        requireLoadableElf("--plugin", plugin);
        const std::size_t known = registry.names().size();
        try {
            plugins.push_back(std::make_unique<PluginLibrary>(plugin));
        } catch (const std::exception& e) {
            throw InputError(fmt::format("--plugin: cannot load '{}': {}", plugin.string(), e.what()));
        }
        if (const auto name = registry.takeConflict()) {
            throw InputError(fmt::format("--plugin: '{}' registers service type '{}', which is already registered",
                                         plugin.string(), *name));
        }
        if (registry.names().size() == known) {
            throw InputError(
                fmt::format("--plugin: '{}' registers no service (a service module registers its types with "
                            "SBSIM_REGISTER_SERVICE)",
                            plugin.string()));
        }
    }
    return plugins;
}

services::ServicesConfig loadServicesConfig(const fs::path& path, FileLedger& files) {
    files.requireInput("--services", path);
    std::optional<services::ServicesConfig> config;
    try {
        config = services::ServicesConfig::load(path);
    } catch (const std::exception& e) {
        throw InputError(fmt::format("--services: {}", e.what()));
    }
    const services::ServiceRegistry& registry = services::ServiceRegistry::instance();
    // Every <service>, a vehicle's or a roadside unit's: a type the registry lacks is bad input now,
    // not a failure when the first station starts.
    for (const services::ServiceSpec* spec : config->allServices()) {
        if (registry.contains(spec->type)) continue;
        throw InputError(fmt::format("--services: {}:{}: unknown service type '{}' (known: {})", path.string(),
                                     spec->line, spec->type, fmt::join(registry.names(), ", ")));
    }
    // Read by the services' parser (a DenService's use cases): inputs all the same.
    for (const fs::path& other : config->otherFiles()) {
        files.addReferencedInput(fmt::format("--services (read from '{}')", path.string()), other);
    }
    // A service's own files (a Python service's .py): inputs too.
    for (const services::ServiceSpec* spec : config->allServices()) {
        for (const fs::path& file : registry.files(*spec)) {
            files.addReferencedInput(
                fmt::format("--services ({}:{}: service '{}')", path.string(), spec->line, spec->type), file);
        }
    }
    return std::move(*config);
}

void addLoadedServiceFiles(const std::vector<services::ServiceSpec>& specs, const fs::path& path, FileLedger& files) {
    const services::ServiceRegistry& registry = services::ServiceRegistry::instance();
    for (const services::ServiceSpec& spec : specs) {
        for (const fs::path& file : registry.files(spec)) {
            files.addReferencedInput(
                fmt::format("--services ({}:{}: service '{}')", path.string(), spec.line, spec.type), file);
        }
    }
}

void checkRadioInput(const CommandLine& options, FileLedger& files) {
    if (!options.radio) return;
    if (!options.services) throw UsageError("--radio: the radio carries the services' messages; give --services");
    files.requireInput("--radio", *options.radio);
}

void checkSumoInputs(const std::filesystem::path& sumocfg, const std::vector<std::string>& words, FileLedger& files) {
    files.requireInput("--sumocfg", sumocfg);
    const SumoOptions options(sumocfg, words);
    options.rejectUnrunnable();
    options.addInputs(files);
    for (const std::filesystem::path& state : options.files("load-state")) {
        checkSumoState(fmt::format("--load-state in {}", options.sourceOf("load-state")), state,
                       options.files("net-file"));
    }
}

ScenarioFiles scenarioFiles(const CommandLine& options, bool withBundledStory) {
    ScenarioFiles files{options.sumocfg.value_or(std::filesystem::path()), options.story};
    if (!options.sumocfg) {
        const BundledScenario bundled = BundledScenario::locate();
        files.sumocfg = bundled.sumocfg;
        if (!files.story && withBundledStory) files.story = bundled.story;
    }
    return files;
}

}  // namespace sbsim::app
