#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace sbsim::storyboard {

/// The vehicles a criterion is about: the ids given, or every vehicle when none were given.
class VehicleSet {
public:
    VehicleSet() = default;
    explicit VehicleSet(std::vector<std::string> ids) : ids_(std::move(ids)) { std::sort(ids_.begin(), ids_.end()); }

    bool all() const { return ids_.empty(); }
    bool contains(std::string_view id) const { return all() || std::binary_search(ids_.begin(), ids_.end(), id); }
    /// "" for all, else "vehicles=[a, b]" (for describe()).
    std::string argument() const {
        if (all()) return "";
        std::string out = "vehicles=[";
        for (std::size_t k = 0; k < ids_.size(); ++k) out += (k == 0 ? "" : ", ") + ids_[k];
        return out + "]";
    }

private:
    std::vector<std::string> ids_;  // sorted
};

}  // namespace sbsim::storyboard
