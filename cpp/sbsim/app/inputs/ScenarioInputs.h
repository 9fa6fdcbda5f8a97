#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/app/cli/CommandLine.h"
#include "sbsim/app/inputs/FileLedger.h"
#include "sbsim/app/inputs/PluginLibrary.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::app {

// A run's service inputs, checked before anything runs: a problem is an InputError (one line, exit 2)
// naming the option and the file. Each file is recorded in `files` as an input.

/// The run's SUMO configuration and story: --sumocfg and --story, or the bundled scenario and (when
/// `withBundledStory` and no --story was given) its story.
struct ScenarioFiles {
    std::filesystem::path sumocfg;
    std::optional<std::filesystem::path> story;
};
ScenarioFiles scenarioFiles(const CommandLine& options, bool withBundledStory);

/// Checks what SUMO will read before it reads it: regular files, no option that keeps SUMO from
/// running, a state it can load.
void checkSumoInputs(const std::filesystem::path& sumocfg, const std::vector<std::string>& words, FileLedger& files);

/// Loads the --plugin libraries in order. Each must be a loadable ELF shared library, given once,
/// and must register at least one service type, none registered before.
std::vector<std::unique_ptr<PluginLibrary>> loadPlugins(const std::vector<std::filesystem::path>& paths,
                                                        FileLedger& files);
/// The --services file, with every service type it names known to the registry.
services::ServicesConfig loadServicesConfig(const std::filesystem::path& path, FileLedger& files);
/// The files of the --services entries `specs` that are known only once their services are loaded
/// (a Python service named by module: its module's file), as inputs: called after the services are
/// made, so an output claimed before that names one is refused all the same.
void addLoadedServiceFiles(const std::vector<services::ServiceSpec>& specs, const std::filesystem::path& path,
                           FileLedger& files);
/// The --radio file as an input; UsageError without --services (the radio carries their messages).
void checkRadioInput(const CommandLine& options, FileLedger& files);

}  // namespace sbsim::app
