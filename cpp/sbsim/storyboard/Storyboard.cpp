#include "sbsim/storyboard/Storyboard.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "sbsim/traffic/StoryboardSignal.h"

namespace sbsim::storyboard {

Storyboard::Storyboard(traffic::VehicleRegistry& registry, EventLog* log)
    : kernel::Module("storyboard"),
      log_(log),
      queries_(std::make_unique<traffic::SumoQueries>()),
      world_(registry, log),
      vehicles_(VehiclePass::SignalOutlet{[this] { return hasListeners(traffic::StoryboardSignal::id); },
                                          [this](const traffic::StoryboardSignal& signal) {
                                              emit(traffic::StoryboardSignal::id,
                                                   static_cast<const kernel::Object&>(signal));
                                          }},
                registry, log) {}

Storyboard::~Storyboard() = default;

traffic::SnapshotColumns Storyboard::columns() const {
    if (stories_.empty() && criteria_.empty()) return {};
    // Speed for the stacks that hold a vehicle's speed (settle()), whatever the conditions read.
    traffic::SnapshotColumns columns = traffic::SnapshotColumns::Speed;
    columns |= conditionColumns_;
    for (const CriterionPtr& c : criteria_) columns |= c->columns();
    return columns;
}

void Storyboard::onColumnsChanged(std::function<void(traffic::SnapshotColumns)> listener) {
    columnsChanged_ = std::move(listener);
    if (columnsChanged_) columnsChanged_(columns());
}

void Storyboard::collectConditions(Condition& root) {
    if (!knownConditions_.insert(&root).second) return;  // shared node: visited once
    conditions_.push_back(&root);
    conditionColumns_ |= root.columns();
    if (const auto r = root.neighbourRadius()) neighbourRadius_ = std::max(neighbourRadius_.value_or(0.0), *r);
    root.forEachChild([this](Condition& child) { collectConditions(child); });
}

void Storyboard::registerStory(StoryPtr story) {
    if (!story) throw std::invalid_argument("registerStory needs a Story, got None");
    const traffic::SnapshotColumns before = columns();
    story->setDefaultName(fmt::format("story{}", stories_.size()));
    // One name, one story: the summary, the event log and every table key stories by name. A set,
    // so registering many stories stays linear.
    if (!storyNames_.insert(story->name()).second) {
        throw std::invalid_argument(fmt::format("two stories are named '{}'; give each its own name", story->name()));
    }
    collectConditions(story->condition());
    if (story->isWorldStory()) {
        world_.addStory(*story);
    } else {
        vehicles_.addStory(*story, stories_.size());
    }
    stories_.push_back(std::move(story));
    if (columnsChanged_ && columns() != before) columnsChanged_(columns());  // the snapshot reads only what is needed
}

void Storyboard::registerCriterion(CriterionPtr criterion) {
    if (!criterion) throw std::invalid_argument("registerCriterion needs a criterion, got None");
    if (criterion->needsEvents()) {
        // Without --events the board keeps a log of its own, in memory only.
        if (log_ == nullptr) {
            ownLog_ = std::make_unique<EventLog>(discarded_);
            log_ = ownLog_.get();
            vehicles_.setLog(log_);
            world_.setLog(log_);
        }
        log_->keepLines();
    }
    criteria_.push_back(std::move(criterion));
    if (columnsChanged_) columnsChanged_(columns());
}

std::vector<std::pair<std::string, CriterionVerdict>> Storyboard::verdicts() const {
    std::vector<std::pair<std::string, CriterionVerdict>> out;
    out.reserve(criteria_.size());
    const CriterionRun run{stories_, statistics_, log_ != nullptr ? std::string_view(log_->keptLines()) : ""};
    for (const CriterionPtr& c : criteria_) out.emplace_back(c->name(), c->verdict(run));
    return out;
}

std::size_t Storyboard::maxConditionStates() const {
    std::size_t most = 0;
    for (const Condition* c : conditions_) most = std::max(most, c->heldVehicles());
    return most;
}

void Storyboard::update(const traffic::VehicleSnapshot& snapshot, std::vector<std::string> left) {
    const auto started = std::chrono::steady_clock::now();
    // The vehicles active since the last pass were active for the time in between.
    if (updated_ && snapshot.time() > now_) {
        const kernel::SimTime elapsed = snapshot.time() - now_;
        for (const StoryPtr& story : stories_) story->counters().elapse(elapsed);
    }
    updated_ = true;
    now_ = snapshot.time();
    std::sort(left.begin(), left.end());
    for (const std::string& id : left) {
        vehicles_.vehicleLeft(id, now_);
        for (Condition* c : conditions_) c->forget(id);
    }

    // Built on first use: a condition that answers from its own sweep ahead never asks.
    grid_.reset(snapshot, std::max(neighbourRadius_.value_or(0.0), 5.0));
    const EvaluationContext ctx(snapshot, grid_, queries_.get(), &simulation().parallel(), stations_.get(),
                                &penetration_);
    for (Condition* c : conditions_) c->prepare(ctx);
    for (const CriterionPtr& c : criteria_) c->prepare(ctx);
    if (!world_.empty()) {
        world_.run(now_);
        vehicles_.setGone(world_.network().removedAfterInsertion());
    }
    vehicles_.run(ctx, simulation().parallel());
    for (const CriterionPtr& c : criteria_) c->observe(ctx);
    if (log_ != nullptr) log_->flush();
    updateSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

}  // namespace sbsim::storyboard
