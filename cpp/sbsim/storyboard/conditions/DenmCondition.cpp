#include "sbsim/storyboard/conditions/DenmCondition.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sbsim::storyboard {

DenmCondition::DenmCondition(std::optional<int> cause, std::optional<kernel::SimTime> maxAge, DenmRelevance relevance)
    : cause_(cause), maxAge_(maxAge), relevance_(relevance) {}

traffic::SnapshotColumns DenmCondition::columns() const {
    if (!relevance_.any()) return {};
    return relevance_.ahead
               ? traffic::SnapshotColumns{traffic::SnapshotColumns::Position, traffic::SnapshotColumns::Angle}
               : traffic::SnapshotColumns::Position;
}

bool DenmCondition::relevant(const facilities::DenmContent& denm, const Eigen::Vector2d& position, double angle) const {
    const Eigen::Vector2d toEvent = denm.eventPosition - position;
    const double distance = toEvent.norm();
    if (relevance_.within && distance > *relevance_.within) return false;
    if (relevance_.ahead) {
        // SUMO's angle: degrees, 0 = north, clockwise; the heading as a unit vector in x (east), y (north).
        const double rad = angle * std::numbers::pi / 180.0;
        const Eigen::Vector2d heading(std::sin(rad), std::cos(rad));
        if (heading.dot(toEvent) <= 0) return false;
    }
    if (relevance_.inRelevanceArea) {
        if (denm.relevanceDistance ? distance > *denm.relevanceDistance : !denm.destination.contains(position))
            return false;
    }
    return true;
}

ConditionResult DenmCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const auto& snapshot = ctx.snapshot();
    const facilities::StationFacilities* station =
        ctx.stations() == nullptr ? nullptr : ctx.stations()->find(snapshot.ids()[ego]);
    if (station == nullptr) return false;
    const kernel::SimTime now = ctx.now();
    bool any = false;
    std::vector<VehicleIndex> originators;
    for (const auto& [action, entry] : station->denms.entries()) {
        if (entry.denm.expiry() < now) continue;
        if (cause_ && entry.denm.cause != *cause_) continue;
        if (maxAge_ && now - entry.lastHeardAt > *maxAge_) continue;
        if (relevance_.any() &&
            !relevant(entry.denm, snapshot.positions().col(ego), relevance_.ahead ? snapshot.angles()[ego] : 0.0))
            continue;
        any = true;
        const auto index = snapshot.indexOf(action.station);
        if (index && *index != ego) originators.push_back(*index);
    }
    if (!any) return false;
    if (originators.empty()) return true;
    std::sort(originators.begin(), originators.end());
    originators.erase(std::unique(originators.begin(), originators.end()), originators.end());
    return ConditionResult::ofOthers(std::move(originators));
}

std::string DenmCondition::describe() const {
    std::string out = "DenmCondition(";
    out += cause_ ? "cause " + std::to_string(*cause_) : "any cause";
    if (maxAge_) out += ", max age " + maxAge_->str() + " s";
    if (relevance_.within) out += fmt::format(", within {:g} m", *relevance_.within);
    if (relevance_.ahead) out += ", ahead";
    if (relevance_.inRelevanceArea) out += ", in relevance area";
    return out + ")";
}

}  // namespace sbsim::storyboard
