#include "sbsim/storyboard/StoryAreas.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <set>

#include "sbsim/storyboard/conditions/DistanceCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"

namespace sbsim::storyboard {

std::vector<StoryArea> conditionAreas(const Condition& root) {
    std::vector<StoryArea> out;
    std::set<const Condition*> seen;
    const std::function<void(const Condition&)> visit = [&](const Condition& c) {
        if (!seen.insert(&c).second) return;
        if (const auto* p = dynamic_cast<const PolygonCondition*>(&c)) {
            out.push_back({&c, p->polygon().vertices(), std::nullopt});
        } else if (const auto* d = dynamic_cast<const DistanceCondition*>(&c); d != nullptr && d->point()) {
            out.push_back({&c, {*d->point()}, d->distance()});
        }
        // forEachChild is non-const only because the board visits to mutate; this walk only reads.
        const_cast<Condition&>(c).forEachChild([&](Condition& child) { visit(child); });
    };
    visit(root);
    return out;
}

std::vector<StoryArea> storyAreas(const Story& story) { return conditionAreas(story.condition()); }

std::vector<Eigen::Vector2d> outline(const StoryArea& area, int circleVertices) {
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
