#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

namespace sbsim::storyboard {

/// Hash for vehicle ids that also accepts string_view, so per-vehicle state is found without
/// building a std::string (test() runs for every vehicle each step).
struct VehicleIdHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view id) const noexcept { return std::hash<std::string_view>{}(id); }
};

/// Per-vehicle state of a condition, keyed by vehicle id (stable while the vehicle runs, unlike its
/// snapshot index).
template <typename T>
using VehicleIdMap = std::unordered_map<std::string, T, VehicleIdHash, std::equal_to<>>;
using VehicleIdSet = std::unordered_set<std::string, VehicleIdHash, std::equal_to<>>;

}  // namespace sbsim::storyboard
