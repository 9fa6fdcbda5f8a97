#include "sbsim/storyboard/StepPairs.h"

#include <algorithm>
#include <functional>

#include "sbsim/storyboard/EvaluationContext.h"

namespace sbsim::storyboard {

void StepPairs::Handover::hand(Index a, Index b, double d2) {
    within_[0].emplace_back(a, b);
    for (std::size_t level = 1; level < levels_ && d2 <= r2_[level]; ++level) within_[level].emplace_back(a, b);
}

void StepPairs::join(User& user) {
    for (std::size_t k = 0; k < joined_; ++k) {
        if (slots_[k].user == &user) return;
    }
    if (joined_ == slots_.size()) slots_.emplace_back();
    slots_[joined_++].user = &user;
}

void StepPairs::run(const EvaluationContext& ctx) {
    const std::size_t users = joined_;
    joined_ = 0;  // they leave whatever happens below
    if (users == 0) return;
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();

    // The first user of the largest radius sweeps; the others' distinct radii, largest first: a
    // pair within the k-th is within all before it.
    std::size_t sweeper = 0;
    for (std::size_t u = 1; u < users; ++u) {
        if (slots_[u].user->pairRadius() > slots_[sweeper].user->pairRadius()) sweeper = u;
    }
    std::swap(slots_[0], slots_[sweeper]);
    const double radius = slots_[0].user->pairRadius();
    levelR2_.clear();
    for (std::size_t u = 1; u < users; ++u) {
        const double r = slots_[u].user->pairRadius();
        levelR2_.push_back(r * r);
    }
    std::sort(levelR2_.begin(), levelR2_.end(), std::greater<>());
    levelR2_.erase(std::unique(levelR2_.begin(), levelR2_.end()), levelR2_.end());
    for (std::size_t u = 1; u < users; ++u) {
        const double r = slots_[u].user->pairRadius();
        slots_[u].level =
            static_cast<std::size_t>(std::find(levelR2_.begin(), levelR2_.end(), r * r) - levelR2_.begin());
    }
    sweep_.build(snapshot, radius);  // tests d2 <= radius·radius: every other radius's pairs are among them
    ++sweeps_;

    const std::size_t rows = sweep_.rows();
    const std::size_t levels = levelR2_.size();
    if (rows_.size() < rows) rows_.resize(rows);
    for (std::size_t u = 0; u < users; ++u) {
        if (slots_[u].rowKept.size() < rows) slots_[u].rowKept.resize(rows);
    }
    const auto body = [&](std::size_t begin, std::size_t end) {
        for (std::size_t row = begin; row < end; ++row) {
            std::vector<std::vector<Pair>>& within = rows_[row];
            if (within.size() < levels) within.resize(levels);
            for (std::size_t level = 0; level < levels; ++level) within[level].clear();
            Handover handover;
            handover.r2_ = levelR2_.data();
            handover.within_ = within.data();
            handover.levels_ = levels;
            std::vector<Pair>& swept = slots_[0].rowKept[row];
            swept.clear();
            slots_[0].user->sweepRow(snapshot, sweep_, row, handover, swept);
            for (std::size_t u = 1; u < users; ++u) {
                Slot& slot = slots_[u];
                std::vector<Pair>& kept = slot.rowKept[row];
                kept.clear();
                slot.user->keepPairs(snapshot, within[slot.level], kept);
            }
        }
    };
    if (ctx.parallel() != nullptr) {
        ctx.parallel()->run(rows, body, 1);
    } else {
        body(0, rows);
    }
    for (std::size_t u = 0; u < users; ++u) {
        Slot& slot = slots_[u];
        slot.kept.clear();
        for (std::size_t row = 0; row < rows; ++row) {
            slot.kept.insert(slot.kept.end(), slot.rowKept[row].begin(), slot.rowKept[row].end());
        }
        std::sort(slot.kept.begin(), slot.kept.end());
        slot.user->pairsKept(snapshot, slot.kept);
    }
}

}  // namespace sbsim::storyboard
