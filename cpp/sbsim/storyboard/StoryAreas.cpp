#include "sbsim/storyboard/StoryAreas.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <set>

namespace sbsim::storyboard {

std::vector<StoryArea> conditionAreas(const Condition& root) {
    std::vector<StoryArea> out;
    std::set<const Condition*> seen;
    const std::function<void(const Condition&)> visit = [&](const Condition& c) {
        if (!seen.insert(&c).second) return;
        if (std::optional<ConditionArea> area = c.area()) {
            StoryArea found;
            static_cast<ConditionArea&>(found) = std::move(*area);
            found.condition = &c;
            out.push_back(std::move(found));
        }
        c.forEachChild(visit);
    };
    visit(root);
    return out;
}

std::vector<StoryArea> storyAreas(const Story& story) { return conditionAreas(story.condition()); }

std::vector<Eigen::Vector2d> outline(const ConditionArea& area, int circleVertices) {
    if (!area.radius) return area.points;
    std::vector<Eigen::Vector2d> out;
    out.reserve(static_cast<std::size_t>(circleVertices));
    for (int k = 0; k < circleVertices; ++k) {
        const double a = 2 * std::numbers::pi * k / circleVertices;
        out.push_back(area.points.front() + *area.radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
    return out;
}

}  // namespace sbsim::storyboard
