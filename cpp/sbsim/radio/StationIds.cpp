#include "sbsim/radio/StationIds.h"

#include <limits>
#include <stdexcept>

namespace sbsim::radio {

StationIds::Index StationIds::intern(std::string_view name) {
    if (const auto it = indices_.find(name); it != indices_.end()) return it->second;
    if (names_.size() >= std::numeric_limits<Index>::max()) throw std::length_error("too many station ids");
    const auto index = static_cast<Index>(names_.size());
    const auto added = indices_.emplace(std::string(name), index).first;
    names_.push_back(&added->first);
    return index;
}

std::optional<StationIds::Index> StationIds::find(std::string_view name) const {
    const auto it = indices_.find(name);
    if (it == indices_.end()) return std::nullopt;
    return it->second;
}

}  // namespace sbsim::radio
