#include "sbsim/storyboard/Storyboard.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>

#include "sbsim/kernel/OneLine.h"
#include "sbsim/storyboard/StoryError.h"
#include "sbsim/storyboard/StoryPalette.h"
#include "sbsim/storyboard/effects/ColorEffect.h"
#include "sbsim/traffic/StoryboardSignal.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::storyboard {

/// The EffectScope of one (vehicle, story, effect) activation.
class Storyboard::Scope : public EffectScope {
public:
    Scope(Storyboard& board, VehicleState& state, const Story& story, const std::string& id,
          const ConditionResult* result = nullptr, const traffic::VehicleSnapshot* snapshot = nullptr)
        : board_(board), state_(state), story_(story), id_(id), result_(result), snapshot_(snapshot) {}

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
    void emitSignal(const std::string& cause, bool onExit) override {
        ++board_.signalsByCause_[cause];
        if (board_.log_ != nullptr) board_.log_->signal(board_.now_, story_.name(), id_, cause, others(), onExit);
        if (!board_.hasListeners(traffic::StoryboardSignal::id)) return;  // nobody to tell: build nothing
        traffic::StoryboardSignal signal;
        signal.cause = cause;
        signal.story = story_.name();
        signal.ego = id_;
        signal.others = others();
        signal.onExit = onExit;
        board_.emit(traffic::StoryboardSignal::id, static_cast<const kernel::Object&>(signal));
    }

private:
    Storyboard& board_;
    VehicleState& state_;
    const Story& story_;
    const std::string& id_;
    const ConditionResult* result_;
    const traffic::VehicleSnapshot* snapshot_;
    mutable std::vector<std::string> others_;
    mutable bool othersReady_ = false;
    traffic::EffectStack::Token token_ = 0;
};

/// The WorldScope of one (world story, effect) activation.
class Storyboard::WorldScopeImpl : public WorldScope {
public:
    WorldScopeImpl(Storyboard& board, const Story& story) : board_(board), story_(story) {}
    void setToken(NetworkStack::Token token) { token_ = token; }

    const Story& story() const override { return story_; }
    kernel::SimTime now() const override { return board_.now_; }
    traffic::NetworkController& network() override { return *board_.network_; }
    NetworkStack& stack() override { return *board_.networkStack_; }
    NetworkStack::Token token() const override { return token_; }

private:
    Storyboard& board_;
    const Story& story_;
    NetworkStack::Token token_ = 0;
};

Storyboard::Storyboard(EventLog* log)
    : kernel::Module("storyboard"),
      log_(log),
      ownRegistry_(std::make_unique<traffic::VehicleRegistry>()),
      registry_(ownRegistry_.get()),
      queries_(std::make_unique<traffic::SumoQueries>()) {
    setNetworkController(std::make_unique<traffic::NetworkController>());
}

void Storyboard::setNetworkController(std::unique_ptr<traffic::NetworkController> network) {
    network_ = std::move(network);
    networkStack_ = std::make_unique<NetworkStack>(*network_, [this](const std::string& message) {
        fmt::print(stderr, "sbsim: warning: t={} s: {}\n", now_.str(), message);
    });
}

Storyboard::~Storyboard() = default;

void Storyboard::attach(kernel::Module& sumo) {
    sumo.subscribe(traffic::SumoBridge::arrivedSignal, *this);
    sumo.subscribe(traffic::SumoBridge::stepSignal, *this);
    bridge_ = dynamic_cast<traffic::SumoBridge*>(&sumo);
    if (bridge_) bridge_->demandColumns(columns());
    if (bridge_ && ownRegistry_) ownRegistry_->attach(*bridge_);
}

void Storyboard::useRegistry(traffic::VehicleRegistry& registry) {
    if (!vehicles_.empty()) throw std::logic_error("Storyboard::useRegistry after vehicles got state");
    registry_ = &registry;
    ownRegistry_.reset();
}

traffic::SnapshotColumns Storyboard::columns() const {
    if (stories_.empty()) return {};
    // Speed for the stacks that hold a vehicle's speed (settle()), whatever the conditions read.
    traffic::SnapshotColumns columns = traffic::SnapshotColumns::Speed;
    for (const Condition* c : conditions_) columns |= c->columns();
    return columns;
}

void Storyboard::receiveSignal(kernel::Module&, kernel::SignalId id, std::string_view value) {
    if (id == traffic::SumoBridge::arrivedSignal) leftSinceStep_.emplace_back(value);
}

void Storyboard::receiveSignal(kernel::Module&, kernel::SignalId id, const kernel::Object& value) {
    if (id != traffic::SumoBridge::stepSignal) return;
    const auto& snapshot = dynamic_cast<const traffic::VehicleSnapshot&>(value);
    if (!equippedOnly_) {
        update(snapshot, std::move(leftSinceStep_));
    } else {
        // Unequipped vehicles are not there for the stories: never an ego, never a neighbour.
        equippedScratch_.clear();
        for (traffic::VehicleSnapshot::Index i = 0; i < snapshot.size(); ++i) {
            if (equippedOnly_->equipped(snapshot.ids()[i])) equippedScratch_.push_back(i);
        }
        equippedView_.assignSubset(snapshot, equippedScratch_);
        std::erase_if(leftSinceStep_, [&](const std::string& id) { return !equippedOnly_->equipped(id); });
        update(equippedView_, std::move(leftSinceStep_));
    }
    leftSinceStep_.clear();
}

void Storyboard::collectConditions(Condition& root) {
    if (!knownConditions_.insert(&root).second) return;  // shared node: visited once
    conditions_.push_back(&root);
    if (const auto r = root.neighbourRadius()) neighbourRadius_ = std::max(neighbourRadius_.value_or(0.0), *r);
    root.forEachChild([this](Condition& child) { collectConditions(child); });
}

void Storyboard::registerStory(StoryPtr story) {
    if (!story) throw std::invalid_argument("registerStory needs a Story, got None");
    if (!story->explicitName_) story->name_ = fmt::format("story{}", stories_.size());
    collectConditions(story->condition());
    const bool world = dynamic_cast<const WorldStory*>(story.get()) != nullptr;
    if (world) worldStories_.push_back(stories_.size());
    world_.push_back(world);
    worldStates_.resize(stories_.size() + 1);
    pure_.push_back(!world && story->condition().pure());
    maxActivations_.push_back(story->maxActivations().value_or(std::numeric_limits<std::uint64_t>::max()));
    if (pure_.back()) pureStories_.push_back(stories_.size());
    stories_.push_back(std::move(story));
    if (bridge_) bridge_->demandColumns(columns());
    precomputed_.resize(stories_.size());
    for (auto& [id, state] : vehicles_) {
        state.applied.resize(stories_.size());
        state.active.resize(stories_.size());
        state.activations.resize(stories_.size());
    }
}

std::size_t Storyboard::maxConditionStates() const {
    std::size_t most = 0;
    for (const Condition* c : conditions_) most = std::max(most, c->heldVehicles());
    return most;
}

bool Storyboard::isActive(const Story& story) const {
    for (const std::size_t s : worldStories_) {
        if (stories_[s].get() == &story) return worldStates_[s].active;
    }
    return false;
}

bool Storyboard::isActive(const std::string& vehicle, const Story& story) const {
    const auto it = vehicles_.find(vehicle);
    if (it == vehicles_.end()) return false;
    for (std::size_t s = 0; s < stories_.size(); ++s) {
        if (stories_[s].get() == &story) return it->second.active[s];
    }
    return false;
}

Storyboard::VehicleState& Storyboard::stateFor(const std::string& id) {
    auto [it, inserted] = vehicles_.try_emplace(id);
    VehicleState& state = it->second;
    if (inserted) {
        state.vehicle = registry_->of(id);
        state.controller = std::shared_ptr<traffic::VehicleController>(state.vehicle, state.vehicle->controller.get());
        state.applied.resize(stories_.size());
        state.active.resize(stories_.size());
        state.activations.resize(stories_.size());
    }
    return state;
}

void Storyboard::update(const traffic::VehicleSnapshot& snapshot, std::vector<std::string> left) {
    const auto started = std::chrono::steady_clock::now();
    // The vehicles active since the last pass were active for the time in between.
    if (updated_ && snapshot.time() > now_) {
        const kernel::SimTime elapsed = snapshot.time() - now_;
        for (const StoryPtr& story : stories_)
            story->activeTime_ += elapsed * static_cast<kernel::SimTime::rep>(story->activeVehicles_);
    }
    updated_ = true;
    now_ = snapshot.time();
    std::sort(left.begin(), left.end());
    for (const std::string& id : left) {
        if (const auto it = vehicles_.find(id); it != vehicles_.end()) {
            for (std::size_t s = 0; s < stories_.size(); ++s) {
                if (!it->second.active[s]) continue;
                --stories_[s]->activeVehicles_;
                if (log_ != nullptr) log_->deactivate(now_, stories_[s]->name(), id, "vehicle_left");
            }
            forgetState(id);
            vehicles_.erase(it);
            registry_->drop(id);
        }
        for (Condition* c : conditions_) c->forget(id);
    }

    if (neighbourRadius_) grid_.build(snapshot, std::max(*neighbourRadius_, 5.0));
    const EvaluationContext ctx(snapshot, grid_, queries_.get(), &simulation().parallel());
    for (Condition* c : conditions_) c->prepare(ctx);
    if (!worldStories_.empty()) updateWorld();

    // All pure stories in one parallel loop: one hand-over to the workers per step, and each
    // vehicle's data is read while still in cache.
    const auto n = static_cast<std::size_t>(snapshot.size());
    // Every element is overwritten below: only the length changes, nothing is rebuilt.
    for (const std::size_t s : pureStories_) precomputed_[s].resize(n, ConditionResult(false));
    if (!pureStories_.empty()) {
        simulation().parallel().run(
            n,
            [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) {
                    for (const std::size_t s : pureStories_)
                        precomputed_[s][i] = stories_[s]->condition().test(ctx, static_cast<VehicleIndex>(i));
                }
            },
            128);
    }

    const auto& ids = snapshot.ids();
    matchStates(ids);
    const std::size_t stride = stories_.size();
    for (VehicleIndex i = 0; i < snapshot.size(); ++i) {
        const std::string& id = ids[i];
        Row& row = rows_[static_cast<std::size_t>(i)];
        std::uint8_t* const active = activeFlags_.data() + static_cast<std::size_t>(i) * stride;
        bool changed = false;
        for (std::size_t s = 0; s < stride; ++s) {
            if (world_[s]) continue;
            ConditionResult tested(false);
            const ConditionResult& result =
                pure_[s] ? precomputed_[s][i] : (tested = stories_[s]->condition().test(ctx, i));
            if (!active[s] && result.isTrue()) {
                // A vehicle without state has never activated anything.
                if ((row.state != nullptr ? row.state->activations[s] : 0) >= maxActivations_[s]) continue;
                if (row.state == nullptr) row.state = &stateFor(id);
                activate(*row.state, s, id, result, snapshot);
                active[s] = 1;
                changed = true;
            } else if (active[s] && !result.isTrue()) {
                deactivate(*row.state, s, id);
                active[s] = 0;
                changed = true;
            }
        }
        // A vehicle's state is kept until it leaves, even while idle: stories that flip often
        // (a speed threshold) would otherwise rebuild it again and again.
        if (changed) row.settling = row.state->vehicle->stack.settling();
        if (row.settling) row.state->vehicle->stack.settle(snapshot.speeds()[i]);
    }
    stateIds_ = ids;
    if (log_ != nullptr) log_->flush();
    updateSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void Storyboard::updateWorld() {
    networkStack_->step();
    worldSnapshot_.assign({traffic::VehicleSnapshot::Vehicle{}}, now_);  // one row, id ""
    worldGrid_.build(worldSnapshot_, 100);
    const EvaluationContext ctx(worldSnapshot_, worldGrid_);
    for (const std::size_t s : worldStories_) {
        const bool holds = stories_[s]->condition().test(ctx, 0).isTrue();
        if (holds && !worldStates_[s].active) {
            activateWorld(s);
        } else if (!holds && worldStates_[s].active) {
            deactivateWorld(s);
        }
    }
}

namespace {

/// Runs one world effect's apply or remove; what it throws becomes a StoryError naming the story,
/// the effect and the time (a wrong edge or light id in a script ends the run with exit code 2).
template <typename F>
void worldCommand(const Story& story, const WorldEffect& effect, kernel::SimTime now, F command) {
    try {
        command();
    } catch (const StoryError&) {
        throw;
    } catch (const std::exception& e) {
        throw StoryError(fmt::format("story '{}': {} at t={} s: {}", story.name(), effect.typeName(), now.str(),
                                     kernel::oneLine(e.what())));
    }
}

}  // namespace

void Storyboard::activateWorld(std::size_t s) {
    Story& story = *stories_[s];
    WorldState& state = worldStates_[s];
    state.active = true;
    ++story.activations_;
    ++story.activeVehicles_;
    if (log_ != nullptr) log_->activate(now_, story.name(), std::nullopt);
    WorldScopeImpl scope(*this, story);
    for (const WorldEffectPtr& effect : static_cast<const WorldStory&>(story).worldEffects()) {
        const NetworkStack::Token token = registry_->newToken();
        scope.setToken(token);
        worldCommand(story, *effect, now_, [&] { effect->apply(scope); });
        state.applied.emplace_back(effect.get(), token);
    }
}

void Storyboard::deactivateWorld(std::size_t s) {
    Story& story = *stories_[s];
    WorldState& state = worldStates_[s];
    state.active = false;
    --story.activeVehicles_;
    if (log_ != nullptr) log_->deactivate(now_, story.name(), std::nullopt, "condition");
    WorldScopeImpl scope(*this, story);
    for (auto it = state.applied.rbegin(); it != state.applied.rend(); ++it) {
        scope.setToken(it->second);
        worldCommand(story, *it->first, now_, [&] { it->first->remove(scope); });
    }
    state.applied.clear();
}

void Storyboard::matchStates(const std::vector<std::string>& ids) {
    // Both id lists ascend, so one merge pass carries each vehicle's row over from the last step:
    // a string comparison per vehicle instead of a hash lookup, and the pass then reads dense
    // per-index flags instead of chasing each vehicle's state.
    const std::size_t stride = stories_.size();
    const bool sameStride = stride == flagStride_;
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

void Storyboard::copyFlags(const VehicleState& state, std::uint8_t* row) const {
    for (std::size_t s = 0; s < stories_.size(); ++s) row[s] = state.active[s] ? 1 : 0;
}

void Storyboard::forgetState(const std::string& id) {
    const auto it = std::lower_bound(stateIds_.begin(), stateIds_.end(), id);
    if (it != stateIds_.end() && *it == id) rows_[static_cast<std::size_t>(it - stateIds_.begin())] = Row{};
}

void Storyboard::activate(VehicleState& state, std::size_t s, const std::string& id, const ConditionResult& result,
                          const traffic::VehicleSnapshot& snapshot) {
    Story& story = *stories_[s];
    state.active[s] = true;
    ++state.activations[s];
    ++story.activations_;
    ++story.activeVehicles_;
    if (log_ != nullptr) log_->activate(now_, story.name(), id);
    Scope scope(*this, state, story, id, &result, &snapshot);
    // Removed in reverse order like the effects, so the paint goes last.
    if (paintStories_) applyEffect(scope, state.applied[s], paintOf(s));
    for (const EffectPtr& effect : story.effects()) applyEffect(scope, state.applied[s], *effect);
}

void Storyboard::applyEffect(Scope& scope, std::vector<AppliedEffect>& applied, Effect& effect) {
    const traffic::EffectStack::Token token = registry_->newToken();
    scope.setToken(token);
    effect.apply(scope);
    applied.push_back({&effect, token});
}

Effect& Storyboard::paintOf(std::size_t story) {
    while (paints_.size() <= story) paints_.push_back(std::make_unique<ColorEffect>(storyColour(paints_.size())));
    return *paints_[story];
}

void Storyboard::deactivate(VehicleState& state, std::size_t s, const std::string& id) {
    Story& story = *stories_[s];
    state.active[s] = false;
    --story.activeVehicles_;
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
