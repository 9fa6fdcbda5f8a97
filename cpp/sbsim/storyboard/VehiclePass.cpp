#include "sbsim/storyboard/VehiclePass.h"

#include <algorithm>
#include <limits>

#include "sbsim/storyboard/StoryCommand.h"

namespace sbsim::storyboard {

/// The EffectScope of one (vehicle, story, effect) activation.
class VehiclePass::Scope : public EffectScope {
public:
    Scope(VehiclePass& pass, VehicleState& state, const Story& story, const std::string& id,
          const ConditionResult* result = nullptr, const traffic::VehicleSnapshot* snapshot = nullptr)
        : pass_(pass), state_(state), story_(story), id_(id), result_(result), snapshot_(snapshot) {}

    void setToken(traffic::EffectStack::Token token) { token_ = token; }

    const Story& story() const override { return story_; }
    const std::string& vehicleId() const override { return id_; }
    traffic::VehicleController& vehicle() override { return *state_.controller; }
    VehicleHandle handle() override { return VehicleHandle(id_, state_.controller); }
    traffic::EffectStack& stack() override { return state_.vehicle->stack; }
    traffic::EffectStack::Token token() const override { return token_; }
    /// Converted from snapshot indices on first use: most activations never ask.
    const std::vector<std::string>& others() const override {
        if (!othersReady_) {
            if (result_ != nullptr && snapshot_ != nullptr) {
                others_.reserve(result_->others().size());
                for (const VehicleIndex o : result_->others()) others_.push_back(snapshot_->ids()[o]);
            }
            othersReady_ = true;
        }
        return others_;
    }
    std::shared_ptr<traffic::VehicleController> controllerOf(const std::string& id) override {
        const std::shared_ptr<traffic::VehicleRegistry::Vehicle> other = pass_.registry_.of(id);
        return {other, other->controller.get()};
    }
    void emitSignal(const std::string& cause, bool onExit) override {
        ++pass_.signalsByCause_[cause];
        if (pass_.log_ != nullptr) pass_.log_->signal(pass_.now_, story_.name(), id_, cause, others(), onExit);
        if (!pass_.signals_.listened()) return;  // nobody to tell: build nothing
        traffic::StoryboardSignal signal;
        signal.cause = cause;
        signal.story = story_.name();
        signal.ego = id_;
        signal.others = others();
        signal.onExit = onExit;
        pass_.signals_.send(signal);
    }

private:
    VehiclePass& pass_;
    VehicleState& state_;
    const Story& story_;
    const std::string& id_;
    const ConditionResult* result_;
    const traffic::VehicleSnapshot* snapshot_;
    mutable std::vector<std::string> others_;
    mutable bool othersReady_ = false;
    traffic::EffectStack::Token token_ = 0;
};

VehiclePass::VehiclePass(SignalOutlet signals, traffic::VehicleRegistry& registry, EventLog* log)
    : signals_(std::move(signals)), registry_(registry), log_(log) {}

VehiclePass::~VehiclePass() = default;

void VehiclePass::addStory(Story& story, std::size_t boardIndex) {
    const bool pure = story.condition().pure();
    if (pure) pureStories_.push_back(stories_.size());
    stories_.push_back(
        {&story, boardIndex, pure, story.maxActivations().value_or(std::numeric_limits<std::uint64_t>::max())});
    precomputed_.resize(stories_.size());
    for (auto& [id, state] : vehicles_) {
        state.applied.resize(stories_.size());
        state.active.resize(stories_.size());
        state.activations.resize(stories_.size());
    }
}

bool VehiclePass::isActive(const std::string& vehicle, const Story& story) const {
    const auto it = vehicles_.find(vehicle);
    if (it == vehicles_.end()) return false;
    for (std::size_t s = 0; s < stories_.size(); ++s) {
        if (stories_[s].story == &story) return it->second.active[s];
    }
    return false;
}

VehiclePass::VehicleState& VehiclePass::stateFor(const std::string& id) {
    auto [it, inserted] = vehicles_.try_emplace(id);
    VehicleState& state = it->second;
    if (inserted) {
        state.vehicle = registry_.of(id);
        state.controller = std::shared_ptr<traffic::VehicleController>(state.vehicle, state.vehicle->controller.get());
        state.applied.resize(stories_.size());
        state.active.resize(stories_.size());
        state.activations.resize(stories_.size());
    }
    return state;
}

void VehiclePass::vehicleLeft(const std::string& id, kernel::SimTime now) {
    now_ = now;
    const auto it = vehicles_.find(id);
    if (it == vehicles_.end()) return;
    for (std::size_t s = 0; s < stories_.size(); ++s) {
        if (!it->second.active[s]) continue;
        for (const AppliedEffect& applied : it->second.applied[s]) applied.effect->vehicleLeft(applied.token);
        stories_[s].story->counters().deactivated();
        if (log_ != nullptr) log_->deactivate(now_, stories_[s].story->name(), id, "vehicle_left");
    }
    forgetRow(id);
    vehicles_.erase(it);
    registry_.drop(id);
}

void VehiclePass::run(const EvaluationContext& ctx, kernel::ParallelFor& parallel) {
    now_ = ctx.now();
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    // All pure stories in one parallel loop: one hand-over to the workers per step, and each
    // vehicle's data is read while still in cache.
    const auto n = static_cast<std::size_t>(snapshot.size());
    // Every element is overwritten below: only the length changes, nothing is rebuilt.
    for (const std::size_t s : pureStories_) precomputed_[s].resize(n, ConditionResult(false));
    if (!pureStories_.empty()) {
        parallel.run(
            n,
            [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) {
                    for (const std::size_t s : pureStories_)
                        precomputed_[s][i] = stories_[s].story->condition().test(ctx, static_cast<VehicleIndex>(i));
                }
            },
            128);
    }

    const auto& ids = snapshot.ids();
    matchStates(snapshot);
    const std::size_t stride = stories_.size();
    for (VehicleIndex i = 0; i < snapshot.size(); ++i) {
        const std::string& id = ids[i];
        if (!gone_.empty() && std::binary_search(gone_.begin(), gone_.end(), id)) continue;
        Row& row = rows_[static_cast<std::size_t>(i)];
        std::uint8_t* const active = activeFlags_.data() + static_cast<std::size_t>(i) * stride;
        bool changed = false;
        // Story s's result for the vehicle: activates or deactivates it if it turned on or off.
        const auto apply = [&](std::size_t s, const Entry& entry, const ConditionResult& result) {
            if (!active[s] && result.isTrue()) {
                // A vehicle without state has never activated anything.
                if ((row.state != nullptr ? row.state->activations[s] : 0) >= entry.maxActivations) return;
                if (row.state == nullptr) row.state = &stateFor(id);
                activate(*row.state, s, id, result, snapshot);
                active[s] = 1;
                changed = true;
            } else if (active[s] && !result.isTrue()) {
                deactivate(*row.state, s, id);
                active[s] = 0;
                changed = true;
            }
        };
        for (std::size_t s = 0; s < stride; ++s) {
            const Entry& entry = stories_[s];
            if (entry.pure) {
                // Most pure stories neither turn on nor off: no result is made or dropped for them.
                const ConditionResult& result = precomputed_[s][i];
                if (result.isTrue() != (active[s] != 0)) apply(s, entry, result);
            } else {
                apply(s, entry, entry.story->condition().test(ctx, i));
            }
        }
        // A vehicle's state is kept until it leaves, even while idle: stories that flip often
        // (a speed threshold) would otherwise rebuild it again and again.
        if (changed) row.settling = row.state->vehicle->stack.settling();
        if (row.settling) row.state->vehicle->stack.settle(snapshot.speeds()[i], snapshot.time());
    }
    if (stateIdsVersion_ != snapshot.idsVersion()) {
        stateIds_ = ids;
        stateIdsVersion_ = snapshot.idsVersion();
    }
}

void VehiclePass::matchStates(const traffic::VehicleSnapshot& snapshot) {
    const std::vector<std::string>& ids = snapshot.ids();
    const std::size_t stride = stories_.size();
    const bool sameStride = stride == flagStride_;
    // The same vehicles as in the last pass (no vehicle came or went): every row stays where it is.
    if (sameStride && snapshot.idsVersion() == stateIdsVersion_ && rows_.size() == ids.size()) return;
    // Both id lists ascend, so one merge pass carries each vehicle's row over from the last step:
    // a string comparison per vehicle instead of a hash lookup, and the pass then reads dense
    // per-index flags instead of chasing each vehicle's state.
    rowScratch_.assign(ids.size(), Row{});
    flagScratch_.assign(ids.size() * stride, 0);
    std::size_t matched = 0;
    std::size_t j = 0;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        while (j < stateIds_.size() && stateIds_[j] < ids[k]) ++j;
        if (j == stateIds_.size() || rows_[j].state == nullptr || stateIds_[j] != ids[k]) continue;
        rowScratch_[k] = rows_[j];
        if (sameStride) {
            std::copy_n(activeFlags_.begin() + static_cast<std::ptrdiff_t>(j * stride), stride,
                        flagScratch_.begin() + static_cast<std::ptrdiff_t>(k * stride));
        } else {
            copyFlags(*rows_[j].state, flagScratch_.data() + k * stride);  // stories were added
        }
        ++matched;
    }
    std::swap(rows_, rowScratch_);
    std::swap(activeFlags_, flagScratch_);
    flagStride_ = stride;
    if (matched == vehicles_.size()) return;
    // Some vehicle with state was missing from a snapshot (only snapshots made by hand do that):
    // look the unmatched ones up.
    for (std::size_t k = 0; k < ids.size(); ++k) {
        if (rows_[k].state != nullptr) continue;
        if (const auto it = vehicles_.find(ids[k]); it != vehicles_.end()) {
            rows_[k] = Row{&it->second, it->second.vehicle->stack.settling()};
            copyFlags(it->second, activeFlags_.data() + k * stride);
        }
    }
}

void VehiclePass::copyFlags(const VehicleState& state, std::uint8_t* row) const {
    for (std::size_t s = 0; s < stories_.size(); ++s) row[s] = state.active[s] ? 1 : 0;
}

void VehiclePass::forgetRow(const std::string& id) {
    const auto it = std::lower_bound(stateIds_.begin(), stateIds_.end(), id);
    if (it == stateIds_.end() || *it != id) return;
    const auto k = static_cast<std::size_t>(it - stateIds_.begin());
    rows_[k] = Row{};
    // Its flags too: a row kept in place (matchStates' same vehicles) is read as it is.
    std::fill_n(activeFlags_.begin() + static_cast<std::ptrdiff_t>(k * flagStride_), flagStride_, 0);
}

void VehiclePass::activate(VehicleState& state, std::size_t s, const std::string& id, const ConditionResult& result,
                           const traffic::VehicleSnapshot& snapshot) {
    Story& story = *stories_[s].story;
    state.active[s] = true;
    ++state.activations[s];
    story.counters().activated();
    if (log_ != nullptr) log_->activate(now_, story.name(), id);
    Scope scope(*this, state, story, id, &result, &snapshot);
    // Removed in reverse order like the effects, so an observer's effect goes last.
    if (observer_ != nullptr) {
        if (Effect* dressing = observer_->onActivation(stories_[s].boardIndex))
            applyEffect(scope, story, state.applied[s], *dressing);
    }
    for (const EffectPtr& effect : story.effects()) applyEffect(scope, story, state.applied[s], *effect);
}

void VehiclePass::applyEffect(Scope& scope, const Story& story, std::vector<AppliedEffect>& applied, Effect& effect) {
    const traffic::EffectStack::Token token = registry_.newToken();
    scope.setToken(token);
    storyCommand(story, effect, now_, [&] { effect.apply(scope); });
    applied.push_back({&effect, token});
}

void VehiclePass::deactivate(VehicleState& state, std::size_t s, const std::string& id) {
    Story& story = *stories_[s].story;
    state.active[s] = false;
    story.counters().deactivated();
    if (log_ != nullptr) log_->deactivate(now_, story.name(), id, "condition");
    Scope scope(*this, state, story, id);
    auto& applied = state.applied[s];
    for (auto it = applied.rbegin(); it != applied.rend(); ++it) {
        scope.setToken(it->token);
        it->effect->remove(scope);
    }
    applied.clear();
}

}  // namespace sbsim::storyboard
