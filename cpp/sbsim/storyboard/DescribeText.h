#pragma once

#include <set>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::storyboard {

/// How `sbsim check` writes arguments of conditions and effects, the same for all of them.

/// "120 s", or "end" for the end of time.
SBSIM_API std::string describeTime(kernel::SimTime t);
/// The first five ids, comma separated, then "… (N)" when there are more.
SBSIM_API std::string describeIds(const std::set<std::string>& ids);

}  // namespace sbsim::storyboard
