#include "sbsim/storyboard/DescribeText.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace sbsim::storyboard {

std::string describeTime(kernel::SimTime t) {
    return t == kernel::SimTime::max() ? "end" : fmt::format("{} s", t.str());
}

std::string describeIds(const std::set<std::string>& ids) {
    constexpr std::size_t kShown = 5;
    const std::vector<std::string> shown(ids.begin(), std::next(ids.begin(), std::min(ids.size(), kShown)));
    return fmt::format("{}{}", fmt::join(shown, ", "), ids.size() > kShown ? fmt::format(", … ({})", ids.size()) : "");
}

}  // namespace sbsim::storyboard
