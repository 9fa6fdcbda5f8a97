#pragma once

#include <filesystem>
#include <string>

namespace sbsim::app {

/// Checks that `path` is a shared library this process can load, before dlopen sees it: an ELF
/// file for this machine whose headers and loadable segments all lie within the file. (dlopen
/// maps a truncated library's segments beyond its end and dies of SIGBUS touching them.) Throws
/// InputError naming `option` and the file.
void requireLoadableElf(const std::string& option, const std::filesystem::path& path);

}  // namespace sbsim::app
