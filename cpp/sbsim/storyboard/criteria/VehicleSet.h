#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/storyboard/EvaluationContext.h"

namespace sbsim::storyboard {

/// The vehicles a criterion is about: the ids given, or every vehicle when none were given; with
/// `equippedOnly`, of those only the V2X-equipped ones (EvaluationContext::equipped).
class VehicleSet {
public:
    VehicleSet() = default;
    explicit VehicleSet(std::vector<std::string> ids, bool equippedOnly = false)
        : ids_(std::move(ids)), equippedOnly_(equippedOnly) {
        std::sort(ids_.begin(), ids_.end());
    }

    bool all() const { return ids_.empty(); }
    bool equippedOnly() const { return equippedOnly_; }
    /// Among the ids given (any id when none were given), whatever its equipment.
    bool contains(std::string_view id) const { return all() || std::binary_search(ids_.begin(), ids_.end(), id); }
    /// Whether the criterion judges vehicle `id` at this step.
    bool admits(const EvaluationContext& ctx, std::string_view id) const {
        return contains(id) && (!equippedOnly_ || ctx.equipped(id));
    }
    /// "" for all, else "vehicles=[a, b]" and/or "equipped_only=True" (for describe()).
    std::string argument() const {
        std::string out;
        if (!all()) {
            out = "vehicles=[";
            for (std::size_t k = 0; k < ids_.size(); ++k) out += (k == 0 ? "" : ", ") + ids_[k];
            out += "]";
        }
        if (equippedOnly_) out += out.empty() ? "equipped_only=True" : ", equipped_only=True";
        return out;
    }

private:
    std::vector<std::string> ids_;  // sorted
    bool equippedOnly_ = false;
};

}  // namespace sbsim::storyboard
