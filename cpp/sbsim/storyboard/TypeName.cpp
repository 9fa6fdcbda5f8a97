#include "sbsim/storyboard/TypeName.h"

#include <cxxabi.h>

#include <cstdlib>
#include <memory>

namespace sbsim::storyboard {

std::string typeNameOf(const std::type_info& type) {
    int status = 0;
    const std::unique_ptr<char, void (*)(void*)> full(abi::__cxa_demangle(type.name(), nullptr, nullptr, &status),
                                                      std::free);
    std::string name = status == 0 && full ? full.get() : type.name();
    if (const auto colons = name.rfind("::"); colons != std::string::npos) name.erase(0, colons + 2);
    return name;
}

}  // namespace sbsim::storyboard
