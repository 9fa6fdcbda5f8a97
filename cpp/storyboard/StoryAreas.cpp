#include "sbsim/storyboard/StoryAreas.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <unordered_set>

#include "sbsim/storyboard/conditions/DistanceCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"

namespace sbsim::storyboard {

namespace {

std::vector<Eigen::Vector2d> circle(const Eigen::Vector2d& centre, double radius, int vertices) {
    std::vector<Eigen::Vector2d> out;
    out.reserve(static_cast<std::size_t>(vertices));
    for (int k = 0; k < vertices; ++k) {
        const double a = 2 * std::numbers::pi * k / vertices;
        out.emplace_back(centre + radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
    return out;
}

}  // namespace

std::vector<StoryArea> storyAreas(const std::vector<StoryPtr>& stories, int circleVertices) {
    std::vector<StoryArea> out;
    for (std::size_t s = 0; s < stories.size(); ++s) {
        const Story& story = *stories[s];
        std::unordered_set<const Condition*> seen;
        std::function<void(Condition&)> visit = [&](Condition& c) {
            if (!seen.insert(&c).second) return;
            if (const auto* p = dynamic_cast<const PolygonCondition*>(&c)) {
                out.push_back({s, story.name(), p->polygon().vertices()});
            } else if (const auto* d = dynamic_cast<const DistanceCondition*>(&c); d && d->point()) {
                // A zero radius is a point: still drawn, as a small mark.
                out.push_back({s, story.name(), circle(*d->point(), std::max(d->distance(), 1.0), circleVertices)});
            }
            c.forEachChild(visit);
        };
        visit(story.condition());
    }
    return out;
}

}  // namespace sbsim::storyboard
