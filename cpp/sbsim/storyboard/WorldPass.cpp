#include "sbsim/storyboard/WorldPass.h"

#include <fmt/format.h>

#include <cstdio>

#include "sbsim/storyboard/EvaluationContext.h"
#include "sbsim/storyboard/StoryCommand.h"

namespace sbsim::storyboard {

/// The WorldScope of one (world story, effect) activation.
class WorldPass::Scope : public WorldScope {
public:
    Scope(WorldPass& pass, const Story& story) : pass_(pass), story_(story) {}
    void setToken(NetworkStack::Token token) { token_ = token; }

    const Story& story() const override { return story_; }
    kernel::SimTime now() const override { return pass_.now_; }
    traffic::NetworkController& network() override { return *pass_.network_; }
    NetworkStack& stack() override { return *pass_.networkStack_; }
    NetworkStack::Token token() const override { return token_; }

private:
    WorldPass& pass_;
    const Story& story_;
    NetworkStack::Token token_ = 0;
};

WorldPass::WorldPass(traffic::VehicleRegistry& registry, EventLog* log) : registry_(registry), log_(log) {
    setNetworkController(std::make_unique<traffic::NetworkController>());
}

WorldPass::~WorldPass() = default;

void WorldPass::setNetworkController(std::unique_ptr<traffic::NetworkController> network) {
    network_ = std::move(network);
    networkStack_ = std::make_unique<NetworkStack>(*network_, [this](const std::string& message) {
        fmt::print(stderr, "sbsim: warning: t={} s: {}\n", now_.str(), message);
    });
}

void WorldPass::addStory(Story& story) { stories_.push_back(Entry{&story}); }

bool WorldPass::isActive(const Story& story) const {
    for (const Entry& e : stories_) {
        if (e.story == &story) return e.active;
    }
    return false;
}

void WorldPass::run(kernel::SimTime now) {
    now_ = now;
    networkStack_->step();
    worldSnapshot_.assign({traffic::VehicleSnapshot::Vehicle{}}, now_);  // one row, id ""
    worldGrid_.build(worldSnapshot_, 100);
    const EvaluationContext ctx(worldSnapshot_, worldGrid_);
    for (Entry& entry : stories_) {
        const bool holds = entry.story->condition().test(ctx, 0).isTrue();
        if (holds && !entry.active) {
            activate(entry);
        } else if (!holds && entry.active) {
            deactivate(entry);
        }
    }
}

void WorldPass::activate(Entry& entry) {
    Story& story = *entry.story;
    entry.active = true;
    story.counters().activated();
    if (log_ != nullptr) log_->activate(now_, story.name(), std::nullopt);
    Scope scope(*this, story);
    for (const WorldEffectPtr& effect : story.worldEffects()) {
        const NetworkStack::Token token = registry_.newToken();
        scope.setToken(token);
        storyCommand(story, *effect, now_, [&] { effect->apply(scope); });
        entry.applied.emplace_back(effect.get(), token);
    }
}

void WorldPass::deactivate(Entry& entry) {
    Story& story = *entry.story;
    entry.active = false;
    story.counters().deactivated();
    if (log_ != nullptr) log_->deactivate(now_, story.name(), std::nullopt, "condition");
    Scope scope(*this, story);
    for (auto it = entry.applied.rbegin(); it != entry.applied.rend(); ++it) {
        scope.setToken(it->second);
        storyCommand(story, *it->first, now_, [&] { it->first->remove(scope); });
    }
    entry.applied.clear();
}

}  // namespace sbsim::storyboard
