#include "sbsim/storyboard/StoryCheck.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <functional>
#include <map>
#include <set>

namespace sbsim::storyboard {

namespace {

void describeTree(const Condition& c, int depth, std::vector<DescribedNode>& out) {
    out.push_back({depth, c.describe()});
    c.forEachChild([&](const Condition& child) { describeTree(child, depth + 1, out); });
}

/// Each node of the tree once, depth first in child order (a shared node where it is first reached).
void forEachDistinctNode(const Condition& root, const std::function<void(const Condition&)>& visit) {
    std::set<const Condition*> seen;
    const std::function<void(const Condition&)> walk = [&](const Condition& c) {
        if (!seen.insert(&c).second) return;
        visit(c);
        c.forEachChild(walk);
    };
    walk(root);
}

}  // namespace

std::vector<DescribedNode> describeStory(const Story& story) {
    std::vector<DescribedNode> out;
    if (story.isWorldStory()) out.push_back({1, "world story: acts on the network"});
    describeTree(story.condition(), 1, out);
    for (const EffectPtr& e : story.effects()) out.push_back({1, "→ " + e->describe()});
    for (const WorldEffectPtr& e : story.worldEffects()) out.push_back({1, "→ " + e->describe()});
    return out;
}

std::vector<CheckWarning> checkStories(const std::vector<StoryPtr>& stories, const CheckScenario& scenario) {
    std::set<std::string> spawned;
    for (const StoryPtr& story : stories) {
        for (const WorldEffectPtr& e : story->worldEffects()) {
            for (std::string& id : e->definedVehicles()) spawned.insert(std::move(id));
        }
    }
    CheckContext ctx(scenario, std::move(spawned));
    for (const StoryPtr& story : stories) {
        ctx.beginStory(story->name());
        forEachDistinctNode(story->condition(), [&](const Condition& c) { c.check(ctx); });
        for (const EffectPtr& e : story->effects()) e->check(ctx);
        for (const WorldEffectPtr& e : story->worldEffects()) e->check(ctx);
        std::map<std::string, std::vector<std::string>> byDomain;
        for (const EffectPtr& e : story->effects()) {
            if (const auto domain = e->domain()) byDomain[*domain].push_back(e->describe());
        }
        for (const auto& [domain, effects] : byDomain) {
            if (effects.size() > 1) {
                ctx.warn(fmt::format("effects of the same domain ({}) in one story: {} (the last applied rules)",
                                     domain, fmt::join(effects, ", ")));
            }
        }
    }
    return std::move(ctx.warnings());
}

std::vector<CheckWarning> checkCriteria(const std::vector<CriterionPtr>& criteria, const CheckScenario& scenario) {
    CheckContext ctx(scenario, {});
    for (const CriterionPtr& c : criteria) {
        ctx.beginStory(c->name());
        c->check(ctx);
    }
    return std::move(ctx.warnings());
}

}  // namespace sbsim::storyboard
