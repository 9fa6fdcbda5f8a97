#pragma once

#include <string>
#include <typeinfo>

#include "sbsim/kernel/Export.h"

namespace sbsim::storyboard {

/// A C++ class's name without its namespaces ("sbsim::storyboard::StopEffect" -> "StopEffect"),
/// for messages that name a condition or effect.
SBSIM_API std::string typeNameOf(const std::type_info& type);

}  // namespace sbsim::storyboard
