#include "sbsim/storyboard/Condition.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace sbsim::storyboard {

void Condition::setDepthOver(std::string_view who, std::span<const ConditionPtr> children) {
    std::size_t deepest = 0;
    std::size_t nodes = 1;
    for (const ConditionPtr& child : children) {
        deepest = std::max(deepest, child->depth());
        nodes += child->nodes();  // each at most kMaxNodes: no overflow for any list a script can pass
    }
    if (deepest + 1 > kMaxDepth) {
        throw std::invalid_argument(fmt::format("{}: the condition tree would be {} levels deep; sbsim's limit is {}",
                                                who, deepest + 1, kMaxDepth));
    }
    if (nodes > kMaxNodes) {
        throw std::invalid_argument(
            fmt::format("{}: the condition tree would have {} nodes (a shared condition counted wherever it "
                        "appears); sbsim's limit is {}",
                        who, nodes, kMaxNodes));
    }
    depth_ = deepest + 1;
    nodes_ = nodes;
}

}  // namespace sbsim::storyboard
