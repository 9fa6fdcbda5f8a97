#include "sbsim/storyboard/StoryCheck.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <set>

#include "sbsim/storyboard/StoryAreas.h"
#include "sbsim/storyboard/WorldStory.h"
#include "sbsim/storyboard/conditions/AccelerationCondition.h"
#include "sbsim/storyboard/conditions/AllCondition.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/DeferringCondition.h"
#include "sbsim/storyboard/conditions/DistanceCondition.h"
#include "sbsim/storyboard/conditions/HeadwayCondition.h"
#include "sbsim/storyboard/conditions/HoldCondition.h"
#include "sbsim/storyboard/conditions/LikelihoodCondition.h"
#include "sbsim/storyboard/conditions/LimitCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/SpeedDifferenceCondition.h"
#include "sbsim/storyboard/conditions/StandstillCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/conditions/TtcCondition.h"
#include "sbsim/storyboard/conditions/TypeCondition.h"
#include "sbsim/storyboard/effects/CloseRoadEffect.h"
#include "sbsim/storyboard/effects/ColorEffect.h"
#include "sbsim/storyboard/effects/EmergencyStopEffect.h"
#include "sbsim/storyboard/effects/SignalEffect.h"
#include "sbsim/storyboard/effects/SpawnEffect.h"
#include "sbsim/storyboard/effects/SpeedEffect.h"
#include "sbsim/storyboard/effects/SpeedFactorEffect.h"
#include "sbsim/storyboard/effects/StopEffect.h"
#include "sbsim/storyboard/effects/TrafficLightEffect.h"
#include "sbsim/storyboard/effects/TypeEffect.h"

namespace sbsim::storyboard {

namespace {

using kernel::SimTime;

std::string seconds(SimTime t) { return t == SimTime::max() ? "end" : fmt::format("{} s", t.str()); }

std::string idList(const std::set<std::string>& ids) {
    constexpr std::size_t kShown = 5;
    std::vector<std::string> shown(ids.begin(), std::next(ids.begin(), std::min(ids.size(), kShown)));
    return fmt::format("{}{}", fmt::join(shown, ", "), ids.size() > kShown ? fmt::format(", … ({})", ids.size()) : "");
}

void describeTree(const Condition& c, int depth, std::vector<DescribedNode>& out) {
    out.push_back({depth, describe(c)});
    const_cast<Condition&>(c).forEachChild([&](Condition& child) { describeTree(child, depth + 1, out); });
}

/// Every node of the tree (shared nodes once per path).
void forEachNode(const Condition& c, const std::function<void(const Condition&)>& visit) {
    visit(c);
    const_cast<Condition&>(c).forEachChild([&](Condition& child) { forEachNode(child, visit); });
}

/// The time window a conjunction of operands is bounded to by its direct TimeCondition operands.
std::optional<std::pair<SimTime, SimTime>> windowOf(const std::vector<const Condition*>& operands) {
    std::optional<std::pair<SimTime, SimTime>> window;
    for (const Condition* c : operands) {
        if (const auto* t = dynamic_cast<const TimeCondition*>(c)) {
            if (!window) window = std::pair{t->begin(), t->end()};
            window->first = std::max(window->first, t->begin());
            window->second = std::min(window->second, t->end());
        }
    }
    return window;
}

std::vector<const Condition*> conjunctionOperands(const Condition& c) {
    std::vector<const Condition*> out;
    if (dynamic_cast<const AndCondition*>(&c) != nullptr || dynamic_cast<const AllCondition*>(&c) != nullptr) {
        const_cast<Condition&>(c).forEachChild([&](Condition& child) {
            // And(And(a, b), c): the nested conjunction's time windows bound it too.
            const auto nested = conjunctionOperands(child);
            if (nested.empty()) {
                out.push_back(&child);
            } else {
                out.insert(out.end(), nested.begin(), nested.end());
            }
        });
    }
    return out;
}

/// Where points the script gave in one frame land when read in the other: the canvas frame has
/// its origin at the boundary's top-left with y downwards, SUMO's at its own origin with y up.
std::vector<Eigen::Vector2d> otherFrame(const std::vector<Eigen::Vector2d>& points, const Eigen::Matrix2d& b,
                                        bool givenAsCanvas) {
    std::vector<Eigen::Vector2d> out;
    for (const Eigen::Vector2d& p : points) {
        // Undo the conversion the script's frame made, and apply the other one.
        const Eigen::Vector2d written = givenAsCanvas ? Eigen::Vector2d(p.x() - b(0, 0), b(1, 1) - p.y()) : p;
        out.emplace_back(givenAsCanvas ? written : Eigen::Vector2d(written.x() + b(0, 0), b(1, 1) - written.y()));
    }
    return out;
}

bool overlapsBoundary(const std::vector<Eigen::Vector2d>& points, const Eigen::Matrix2d& b) {
    double xmin = points.front().x(), xmax = xmin, ymin = points.front().y(), ymax = ymin;
    for (const auto& p : points) {
        xmin = std::min(xmin, p.x());
        xmax = std::max(xmax, p.x());
        ymin = std::min(ymin, p.y());
        ymax = std::max(ymax, p.y());
    }
    // b's columns are (xmin, ymin) and (xmax, ymax).
    return xmax >= b(0, 0) && xmin <= b(0, 1) && ymax >= b(1, 0) && ymin <= b(1, 1);
}

/// The domain a built-in effect commands (two in one story fight over it), if any.
std::optional<std::string> domainOf(const Effect& e) {
    if (dynamic_cast<const SpeedEffect*>(&e) || dynamic_cast<const StopEffect*>(&e) ||
        dynamic_cast<const EmergencyStopEffect*>(&e)) {
        return "speed";
    }
    if (dynamic_cast<const SpeedFactorEffect*>(&e)) return "speed factor";
    if (dynamic_cast<const TypeEffect*>(&e)) return "type";
    if (dynamic_cast<const ColorEffect*>(&e)) return "colour";
    return std::nullopt;
}

}  // namespace

std::string describe(const Condition& c) {
    if (const auto* t = dynamic_cast<const TimeCondition*>(&c)) {
        return fmt::format("TimeCondition({}, {})", seconds(t->begin()), seconds(t->end()));
    }
    if (const auto* s = dynamic_cast<const SpeedConditionGreater*>(&c)) {
        return fmt::format("SpeedConditionGreater({:g} m/s)", s->threshold());
    }
    if (const auto* s = dynamic_cast<const SpeedConditionLess*>(&c)) {
        return fmt::format("SpeedConditionLess({:g} m/s)", s->threshold());
    }
    if (const auto* p = dynamic_cast<const PolygonCondition*>(&c)) {
        std::vector<std::string> points;
        for (const auto& v : p->polygon().vertices()) points.push_back(fmt::format("({:g}, {:g})", v.x(), v.y()));
        return fmt::format("PolygonCondition({} points, SUMO frame: {})", points.size(), fmt::join(points, " "));
    }
    if (const auto* s = dynamic_cast<const CarSetCondition*>(&c))
        return fmt::format("CarSetCondition({})", idList(s->ids()));
    if (const auto* l = dynamic_cast<const LimitCondition*>(&c)) return fmt::format("LimitCondition({})", l->limit());
    if (const auto* d = dynamic_cast<const SpeedDifferenceCondition*>(&c)) {
        const bool faster = dynamic_cast<const SpeedDifferenceConditionFaster*>(&c) != nullptr;
        return fmt::format("SpeedDifferenceCondition{}({:g} m/s{})", faster ? "Faster" : "Slower", d->delta(),
                           d->distance() ? fmt::format(", within {:g} m", *d->distance()) : "");
    }
    if (const auto* t = dynamic_cast<const TtcCondition*>(&c)) {
        return fmt::format("TtcCondition({:g} s, within {:g} m)", t->ttc(), t->distance());
    }
    if (const auto* d = dynamic_cast<const DistanceCondition*>(&c)) {
        const std::string target = d->vehicle() ? fmt::format("vehicle {}", *d->vehicle())
                                                : fmt::format("({:g}, {:g})", d->point()->x(), d->point()->y());
        return fmt::format("DistanceCondition({}, {:g} m)", target, d->distance());
    }
    if (const auto* h = dynamic_cast<const HeadwayCondition*>(&c))
        return fmt::format("HeadwayCondition({:g} s)", h->seconds());
    if (const auto* h = dynamic_cast<const HoldCondition*>(&c))
        return fmt::format("HoldCondition({})", seconds(h->duration()));
    if (const auto* s = dynamic_cast<const StandstillCondition*>(&c)) {
        return fmt::format("StandstillCondition({})", seconds(s->duration()));
    }
    if (const auto* l = dynamic_cast<const LikelihoodCondition*>(&c))
        return fmt::format("LikelihoodCondition({:g})", l->probability());
    if (const auto* d = dynamic_cast<const DeferringCondition*>(&c)) {
        return fmt::format("DeferringCondition({} to {})", seconds(d->minDeferral()), seconds(d->maxDeferral()));
    }
    if (const auto* a = dynamic_cast<const AccelerationConditionGreater*>(&c)) {
        return fmt::format("AccelerationConditionGreater({:g} m/s²)", a->threshold());
    }
    if (const auto* a = dynamic_cast<const AccelerationConditionLess*>(&c)) {
        return fmt::format("AccelerationConditionLess({:g} m/s²)", a->threshold());
    }
    if (const auto* t = dynamic_cast<const TypeCondition*>(&c)) return fmt::format("TypeCondition('{}')", t->pattern());
    return c.typeName();
}

std::string describe(const Effect& e) {
    if (const auto* s = dynamic_cast<const SpeedEffect*>(&e)) return fmt::format("SpeedEffect({:g} m/s)", s->speed());
    if (const auto* f = dynamic_cast<const SpeedFactorEffect*>(&e))
        return fmt::format("SpeedFactorEffect({:g})", f->factor());
    if (const auto* s = dynamic_cast<const SignalEffect*>(&e)) {
        return fmt::format("SignalEffect('{}'{})", s->cause(),
                           s->onExit() ? fmt::format(", on exit '{}'", *s->onExit()) : "");
    }
    if (const auto* t = dynamic_cast<const TypeEffect*>(&e)) return fmt::format("TypeEffect('{}')", t->typeId());
    return e.typeName();
}

std::string describe(const WorldEffect& e) {
    if (const auto* c = dynamic_cast<const CloseRoadEffect*>(&e))
        return fmt::format("CloseRoadEffect({})", fmt::join(c->edges(), ", "));
    if (const auto* t = dynamic_cast<const TrafficLightEffect*>(&e))
        return fmt::format("TrafficLightEffect('{}', '{}')", t->tls(), t->state());
    if (const auto* s = dynamic_cast<const SpawnEffect*>(&e)) {
        const SpawnEffect::Spec& spec = s->spec();
        const std::string way = spec.route.empty() ? fmt::format("{} to {}", spec.from, spec.to)
                                                   : fmt::format("route {}", fmt::join(spec.route, " "));
        return fmt::format("SpawnEffect('{}', {}{})", spec.id, way, spec.type ? ", type " + *spec.type : "");
    }
    return e.typeName();
}

std::vector<DescribedNode> describeStory(const Story& story) {
    std::vector<DescribedNode> out;
    const auto* world = dynamic_cast<const WorldStory*>(&story);
    if (world != nullptr) out.push_back({1, "world story: acts on the network"});
    describeTree(story.condition(), 1, out);
    for (const EffectPtr& e : story.effects()) out.push_back({1, "→ " + describe(*e)});
    if (world != nullptr) {
        for (const WorldEffectPtr& e : world->worldEffects()) out.push_back({1, "→ " + describe(*e)});
    }
    return out;
}

std::vector<CheckWarning> checkStories(const std::vector<StoryPtr>& stories, const CheckScenario& scenario) {
    std::vector<CheckWarning> out;
    const Eigen::Matrix2d& b = scenario.boundary;
    const SimTime runEnd = scenario.end.value_or(SimTime::max());
    // Vehicles the stories add themselves are as defined as the route files' ones.
    std::set<std::string> spawned;
    for (const StoryPtr& story : stories) {
        if (const auto* world = dynamic_cast<const WorldStory*>(story.get())) {
            for (const WorldEffectPtr& e : world->worldEffects()) {
                if (const auto* s = dynamic_cast<const SpawnEffect*>(e.get())) spawned.insert(s->spec().id);
            }
        }
    }
    for (const StoryPtr& story : stories) {
        const auto warn = [&](std::string message) { out.push_back({story->name(), std::move(message)}); };
        // The story's areas as the GUI and the report draw them (each shared polygon once).
        for (const StoryArea& area : storyAreas(*story)) {
            const auto* p = dynamic_cast<const PolygonCondition*>(area.condition);
            if (p == nullptr || area.points.empty() || overlapsBoundary(area.points, b)) continue;
            const bool canvas = p->givenFrame() == PolygonCondition::GivenFrame::Canvas;
            std::string hint = "; read in the other frame it misses the network too";
            if (overlapsBoundary(otherFrame(area.points, b, canvas), b)) {
                hint = canvas ? "; it fits in the SUMO frame: give its points as (x, y) tuples, not Coord"
                              : "; it fits in Artery's canvas frame: give its points as Coord(x, y), not tuples";
            }
            warn(fmt::format("{} lies outside the network boundary ({:g}, {:g})-({:g}, {:g}){}", describe(*p), b(0, 0),
                             b(1, 0), b(0, 1), b(1, 1), hint));
        }
        forEachNode(story->condition(), [&](const Condition& c) {
            if (const auto* t = dynamic_cast<const TimeCondition*>(&c)) {
                if (t->begin() >= runEnd || t->end() <= scenario.begin) {
                    warn(fmt::format("{} lies outside the run ({} to {})", describe(c), seconds(scenario.begin),
                                     seconds(runEnd)));
                }
            } else if (const auto* l = dynamic_cast<const LimitCondition*>(&c)) {
                if (l->limit() == 0) warn("LimitCondition(0) admits no vehicle: the story never activates");
            } else if (const auto* s = dynamic_cast<const CarSetCondition*>(&c)) {
                if (!scenario.vehicleDefined) return;
                std::set<std::string> unknown;
                for (const std::string& id : s->ids()) {
                    if (!scenario.vehicleDefined(id) && !spawned.contains(id)) unknown.insert(id);
                }
                if (!unknown.empty())
                    warn(fmt::format("CarSetCondition names vehicles no route file defines: {}", idList(unknown)));
            }
            if (const auto window = windowOf(conjunctionOperands(c)); window && window->first >= window->second) {
                warn(fmt::format("{} can never hold: its time windows do not overlap", c.typeName()));
            }
        });
        std::map<std::string, std::vector<std::string>> byDomain;
        for (const EffectPtr& e : story->effects()) {
            if (const auto domain = domainOf(*e)) byDomain[*domain].push_back(describe(*e));
        }
        for (const auto& [domain, effects] : byDomain) {
            if (effects.size() > 1) {
                warn(fmt::format("effects of the same domain ({}) in one story: {} (the last applied rules)", domain,
                                 fmt::join(effects, ", ")));
            }
        }
    }
    return out;
}

}  // namespace sbsim::storyboard
