#include "sbsim/storyboard/conditions/RelativeDistanceCondition.h"

#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sbsim::storyboard {

namespace {

/// A vehicle's outline: centre, unit heading, half length and half width.
struct Box {
    Eigen::Vector2d centre;
    Eigen::Vector2d heading;
    double halfLength;
    double halfWidth;

    Eigen::Vector2d normal() const { return {-heading.y(), heading.x()}; }
    std::array<Eigen::Vector2d, 4> corners() const {
        const Eigen::Vector2d l = heading * halfLength;
        const Eigen::Vector2d w = normal() * halfWidth;
        return {centre + l + w, centre + l - w, centre - l - w, centre - l + w};
    }
    /// Half its extent along unit direction `d`.
    double halfExtent(const Eigen::Vector2d& d) const {
        return std::abs(heading.dot(d)) * halfLength + std::abs(normal().dot(d)) * halfWidth;
    }
};

Box boxOf(const traffic::VehicleSnapshot& s, VehicleIndex i) {
    // SUMO's angle: degrees clockwise from north; its position is the front bumper's centre.
    const double a = s.angles()[i] * std::numbers::pi / 180.0;
    const Eigen::Vector2d heading(std::sin(a), std::cos(a));
    const double length = s.lengths()[i];
    return {s.positions().col(i) - heading * (length / 2), heading, length / 2, s.widths()[i] / 2};
}

double pointToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - p).norm();
}

/// Whether two boxes overlap: no separating axis among their four edge directions.
bool overlap(const Box& a, const Box& b) {
    const Eigen::Vector2d d = b.centre - a.centre;
    for (const Eigen::Vector2d& axis : {a.heading, a.normal(), b.heading, b.normal()}) {
        if (std::abs(d.dot(axis)) > a.halfExtent(axis) + b.halfExtent(axis)) return false;
    }
    return true;
}

/// The distance between the outlines of two boxes (0 when they overlap).
double gap(const Box& a, const Box& b) {
    if (overlap(a, b)) return 0;
    const auto ca = a.corners();
    const auto cb = b.corners();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < 4; ++k) {
        for (const Eigen::Vector2d& p : cb) best = std::min(best, pointToSegment(p, ca[k], ca[(k + 1) % 4]));
        for (const Eigen::Vector2d& p : ca) best = std::min(best, pointToSegment(p, cb[k], cb[(k + 1) % 4]));
    }
    return best;
}

}  // namespace

RelativeDistanceCondition::RelativeDistanceCondition(std::string vehicle, double value, ComparisonRule rule, Kind kind,
                                                     bool freespace)
    : vehicle_(std::move(vehicle)), value_(value), rule_(rule), kind_(kind), freespace_(freespace) {
    if (vehicle_.empty()) throw std::invalid_argument("RelativeDistanceCondition: the vehicle id is empty");
    if (!std::isfinite(value) || value < 0) {
        throw std::invalid_argument(
            fmt::format("RelativeDistanceCondition: the distance must be finite and >= 0, not {:g}", value));
    }
}

void RelativeDistanceCondition::prepare(const EvaluationContext& ctx) {
    stamp_ = SnapshotStamp::of(ctx.snapshot());
    target_ = ctx.snapshot().indexOf(vehicle_);
}

double RelativeDistanceCondition::distance(const traffic::VehicleSnapshot& snapshot, VehicleIndex ego,
                                           VehicleIndex target) const {
    const Box e = boxOf(snapshot, ego);
    const Box t = boxOf(snapshot, target);
    const Eigen::Vector2d d = t.centre - e.centre;
    switch (kind_) {
        case Kind::Cartesian:
            return freespace_ ? gap(e, t) : d.norm();
        case Kind::Longitudinal: {
            const double along = std::abs(d.dot(e.heading));
            return freespace_ ? std::max(0.0, along - e.halfLength - t.halfExtent(e.heading)) : along;
        }
        case Kind::Lateral: {
            const double across = std::abs(d.dot(e.normal()));
            return freespace_ ? std::max(0.0, across - e.halfWidth - t.halfExtent(e.normal())) : across;
        }
    }
    return d.norm();
}

ConditionResult RelativeDistanceCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    const std::optional<VehicleIndex> target =
        stamp_ == SnapshotStamp::of(snapshot) ? target_ : snapshot.indexOf(vehicle_);
    if (!target || *target == ego) return ConditionResult::ofOthers({});
    if (!compare(rule_, distance(snapshot, ego, *target), value_, kEqualTolerance))
        return ConditionResult::ofOthers({});
    return ConditionResult::ofOthers({*target});
}

std::string_view RelativeDistanceCondition::kindName(Kind kind) {
    switch (kind) {
        case Kind::Longitudinal:
            return "longitudinal";
        case Kind::Lateral:
            return "lateral";
        case Kind::Cartesian:
            return "cartesian";
    }
    return "cartesian";
}

std::optional<RelativeDistanceCondition::Kind> RelativeDistanceCondition::kindNamed(std::string_view name) {
    for (const Kind k : {Kind::Longitudinal, Kind::Lateral, Kind::Cartesian}) {
        if (kindName(k) == name) return k;
    }
    return std::nullopt;
}

std::string RelativeDistanceCondition::describe() const {
    return fmt::format("RelativeDistanceCondition(vehicle {}, {} {}, {} {:g} m)", vehicle_, kindName(kind_),
                       freespace_ ? "freespace" : "reference points", ruleName(rule_), value_);
}

}  // namespace sbsim::storyboard
