#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sbsim/app/PluginLibrary.h"
#include "sbsim/app/RunFiles.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::app {

// A run's service inputs, checked before anything runs: a problem is an InputError (one line, exit 2)
// naming the option and the file. Each file is recorded in `files` as an input.

/// Loads the --plugin libraries in order. Each must be a loadable ELF shared library, given once,
/// and must register at least one service type, none registered before.
std::vector<std::unique_ptr<PluginLibrary>> loadPlugins(const std::vector<std::filesystem::path>& paths,
                                                        RunFiles& files);
/// The --services file, with every service type it names known to the registry.
services::ServicesConfig loadServicesConfig(const std::filesystem::path& path, RunFiles& files);

}  // namespace sbsim::app
