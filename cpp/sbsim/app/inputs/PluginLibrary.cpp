#include "sbsim/app/inputs/PluginLibrary.h"

#include <dlfcn.h>
#include <fmt/format.h>

#include <string>

namespace sbsim::app {

PluginLibrary::PluginLibrary(const std::filesystem::path& path) {
    // A bare file name would make dlopen search the system paths; a path finds the file given.
    const std::filesystem::path resolved = path.has_parent_path() ? path : std::filesystem::path(".") / path;
    handle_ = dlopen(resolved.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (handle_ == nullptr) {
        const char* error = dlerror();
        throw std::runtime_error(error != nullptr ? error : fmt::format("cannot load {}", path.string()));
    }
}

PluginLibrary::~PluginLibrary() {
    // Kept loaded: registered factories and vtables of its services may still be referenced
    // while the process winds down.
    handle_ = nullptr;
}

}  // namespace sbsim::app
