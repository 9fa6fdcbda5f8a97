#pragma once

#include <filesystem>
#include <stdexcept>

namespace sbsim::app {

/// A shared library of service modules (built with sbsim_add_service_module), loaded for the
/// whole run: its SBSIM_REGISTER_SERVICE lines add its types to the registry as it loads.
class PluginLibrary {
public:
    /// Throws std::runtime_error with the loader's message.
    explicit PluginLibrary(const std::filesystem::path& path);
    ~PluginLibrary();
    PluginLibrary(const PluginLibrary&) = delete;
    PluginLibrary& operator=(const PluginLibrary&) = delete;

private:
    void* handle_ = nullptr;
};

}  // namespace sbsim::app
