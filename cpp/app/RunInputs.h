#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sbsim/app/PluginLibrary.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::app {

// A run's input files, checked before anything runs: a problem is an InputError (one line, exit 2)
// naming the option and the file.

/// Throws unless `path` exists, is not a directory and can be read.
void requireReadableFile(const std::string& option, const std::filesystem::path& path);
/// Loads the --plugin libraries in order; each must register only service types nobody registered yet.
std::vector<std::unique_ptr<PluginLibrary>> loadPlugins(const std::vector<std::filesystem::path>& paths);
/// The --services file, with every service type it names known to the registry.
services::ServicesConfig loadServicesConfig(const std::filesystem::path& path);

}  // namespace sbsim::app
