// The laws of OpenSCENARIO-grade transitions (shapes, progress by time, distance and rate; speed
// and lateral transitions step by step) with results computed by hand, and how the effect stack
// commands them next to holds.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/traffic/EffectStack.h"
#include "sbsim/traffic/LateralTransition.h"
#include "sbsim/traffic/SpeedTransition.h"
#include "sbsim/traffic/Transition.h"

namespace sbsim::traffic {
namespace {

using Shape = Transition::Shape;
using Dimension = Transition::Dimension;

TEST(Transition, ShapesGoFromZeroToOne) {
    for (const Shape s : {Shape::Linear, Shape::Cubic, Shape::Sinusoidal}) {
        EXPECT_DOUBLE_EQ(Transition::shaped(s, 0.0), 0.0);
        EXPECT_DOUBLE_EQ(Transition::shaped(s, 1.0), 1.0);
        EXPECT_DOUBLE_EQ(Transition::shaped(s, 0.5), 0.5) << "all three are symmetric about the midpoint";
        EXPECT_DOUBLE_EQ(Transition::shaped(s, -1.0), 0.0);
        EXPECT_DOUBLE_EQ(Transition::shaped(s, 2.0), 1.0);
    }
    EXPECT_DOUBLE_EQ(Transition::shaped(Shape::Step, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(Transition::shaped(Shape::Linear, 0.25), 0.25);
    EXPECT_DOUBLE_EQ(Transition::shaped(Shape::Cubic, 0.25), 3 * 0.0625 - 2 * 0.015625);  // 0.15625
    EXPECT_NEAR(Transition::shaped(Shape::Sinusoidal, 0.25), (1 - std::sqrt(0.5)) / 2, 1e-15);
}

TEST(Transition, ProgressByTimeDistanceAndRate) {
    const Transition time{Shape::Linear, Dimension::Time, 4.0};
    EXPECT_DOUBLE_EQ(time.progress(1.0, 99.0, 5.0), 0.25);
    EXPECT_DOUBLE_EQ(time.progress(5.0, 0.0, 5.0), 1.0);
    const Transition distance{Shape::Linear, Dimension::Distance, 50.0};
    EXPECT_DOUBLE_EQ(distance.progress(99.0, 10.0, 5.0), 0.2);
    const Transition rate{Shape::Linear, Dimension::Rate, 2.0};  // 2 m/s² for a change of -6 m/s: 3 s
    EXPECT_DOUBLE_EQ(rate.progress(1.5, 0.0, -6.0), 0.5);
    EXPECT_TRUE(rate.done(3.0, 0.0, -6.0));
    EXPECT_DOUBLE_EQ(rate.progress(0.0, 0.0, 0.0), 1.0) << "nothing to change: done";
    EXPECT_DOUBLE_EQ((Transition{Shape::Step, Dimension::Time, 4.0}.progress(0.0, 0.0, 1.0)), 1.0);
}

TEST(Transition, NamesAndDescriptions) {
    EXPECT_EQ(Transition::shapeNamed("cubic"), Shape::Cubic);
    EXPECT_FALSE(Transition::shapeNamed("Cubic").has_value());
    EXPECT_EQ(Transition::dimensionNamed("rate"), Dimension::Rate);
    EXPECT_FALSE(Transition::dimensionNamed("speed").has_value());
    EXPECT_EQ((Transition{Shape::Linear, Dimension::Time, 4}.describe()), "linear over 4 s");
    EXPECT_EQ((Transition{Shape::Cubic, Dimension::Distance, 50}.describe()), "cubic over 50 m");
    EXPECT_EQ((Transition{Shape::Linear, Dimension::Rate, 2}.describe("m/s²")), "linear at 2 m/s²");
    EXPECT_EQ((Transition{Shape::Step, Dimension::Time, 0}.describe()), "step");
}

/// Runs `transition` from t = 0 with step `dt` on a vehicle that takes each commanded speed at
/// once (Euler: it drives the new speed over the step); the commanded speeds by the time they hold.
std::vector<std::pair<double, double>> drive(SpeedTransition transition, double speed, double dt, int steps) {
    std::vector<std::pair<double, double>> out;
    double driven = 0;
    for (int k = 0; k < steps; ++k) {
        const double now = k * dt;
        speed = transition.next(now, dt, speed, driven);
        driven += speed * dt;
        out.emplace_back(now + dt, speed);
    }
    return out;
}

TEST(SpeedTransition, LinearOverFourSecondsReachesTheTargetAtFourSeconds) {
    const auto run =
        drive(SpeedTransition({Shape::Linear, Dimension::Time, 4.0}, {SpeedTarget::Kind::Absolute, 20}), 10.0, 0.1, 60);
    for (const auto& [t, v] : run) {
        if (t <= 4.0 + 1e-9) {
            EXPECT_NEAR(v, 10 + 2.5 * t, 1e-9) << t;
        } else {
            EXPECT_DOUBLE_EQ(v, 20.0) << "held after: " << t;
        }
    }
}

TEST(SpeedTransition, CubicPassesTheMidpointAtHalfTime) {
    const auto run =
        drive(SpeedTransition({Shape::Cubic, Dimension::Time, 4.0}, {SpeedTarget::Kind::Absolute, 0}), 20.0, 0.5, 10);
    EXPECT_NEAR(run[3].second, 10.0, 1e-9) << "t = 2 s";
    EXPECT_NEAR(run[0].second, 20 - 20 * (3.0 / 64 - 2.0 / 512), 1e-9) << "t = 0.5 s: x = 1/8";
    EXPECT_DOUBLE_EQ(run[7].second, 0.0);
}

TEST(SpeedTransition, RateTakesTheChangeOverTheRate) {
    // 30 → 18 m/s at 3 m/s²: 4 s.
    const auto run = drive(SpeedTransition({Shape::Linear, Dimension::Rate, 3.0}, {SpeedTarget::Kind::Absolute, 18}),
                           30.0, 0.25, 24);
    EXPECT_NEAR(run[7].second, 24.0, 1e-9) << "t = 2 s";
    EXPECT_NEAR(run[15].second, 18.0, 1e-9) << "t = 4 s";
    EXPECT_GT(run[14].second, 18.0) << "t = 3.75 s";
}

TEST(SpeedTransition, DistanceReachesTheTargetAfterTheDistance) {
    // 10 → 20 m/s linearly over 150 m (v(s) = 10 + s/15): it gets there after 150 m, within a step's drive.
    SpeedTransition transition({Shape::Linear, Dimension::Distance, 150.0}, {SpeedTarget::Kind::Absolute, 20});
    double speed = 10;
    double driven = 0;
    const double dt = 0.1;
    std::optional<double> reachedAt;
    for (int k = 0; k < 200; ++k) {
        speed = transition.next(k * dt, dt, speed, driven);
        driven += speed * dt;
        if (!reachedAt && speed >= 20 - 1e-9) reachedAt = driven;
        if (driven < 140) EXPECT_NEAR(speed, 10 + driven / 15, 0.15) << driven;
    }
    ASSERT_TRUE(reachedAt.has_value());
    EXPECT_NEAR(*reachedAt, 150.0, 20 * dt);
}

TEST(SpeedTransition, RelativeTargetsFollowTheReference) {
    double reference = 15;
    const auto read = [&reference]() -> std::optional<double> { return reference; };
    const Transition step{Shape::Step, Dimension::Time, 0};
    SpeedTransition once(step, {SpeedTarget::Kind::Delta, -3, read, false});
    SpeedTransition continuous(step, {SpeedTarget::Kind::Delta, -3, read, true});
    SpeedTransition factor(step, {SpeedTarget::Kind::Factor, 0.5, read, true});
    EXPECT_DOUBLE_EQ(once.next(0, 1, 10, 0), 12.0);
    EXPECT_DOUBLE_EQ(continuous.next(0, 1, 10, 0), 12.0);
    EXPECT_DOUBLE_EQ(factor.next(0, 1, 10, 0), 7.5);
    reference = 25;
    EXPECT_DOUBLE_EQ(once.next(1, 1, 12, 0), 12.0) << "read once, at the start";
    EXPECT_DOUBLE_EQ(continuous.next(1, 1, 12, 0), 22.0);
    EXPECT_DOUBLE_EQ(factor.next(1, 1, 7.5, 0), 12.5);
    SpeedTransition gone(step, {SpeedTarget::Kind::Delta, 2, [] { return std::optional<double>(); }, true});
    EXPECT_DOUBLE_EQ(gone.next(0, 1, 9, 0), 9.0) << "no reference at the start: the vehicle keeps its speed";
    SpeedTransition below(step, {SpeedTarget::Kind::Delta, -30, read, false});
    EXPECT_DOUBLE_EQ(below.next(0, 1, 9, 0), 0.0) << "no negative speeds";
}

TEST(LateralTransition, AcrossTheRoadFromItsRightEdge) {
    const std::vector<double> widths{3.2, 3.5, 3.0};
    EXPECT_DOUBLE_EQ((LateralPlace{0, 0}.across(widths)), 1.6);
    EXPECT_DOUBLE_EQ((LateralPlace{1, 0.5}.across(widths)), 3.2 + 1.75 + 0.5);
    EXPECT_DOUBLE_EQ((LateralPlace{7, 0}.across(widths)), 3.2 + 3.5 + 1.5) << "past the last lane: the last";
    EXPECT_DOUBLE_EQ((LateralPlace{-1, 0}.across(widths)), 1.6);
}

TEST(LateralTransition, SinusoidalLaneChangeOverThreeSeconds) {
    const std::vector<double> widths{3.2, 3.2, 3.2};
    LateralTransition change({Shape::Sinusoidal, Dimension::Time, 3.0}, {1, 0});
    LateralPlace place{0, 0};
    const double dt = 0.1;
    double y = place.across(widths);
    for (int k = 0; k < 40; ++k) {
        const double move = change.next(k * dt, dt, place, widths, 20, 0);
        y += move;
        const double t = (k + 1) * dt;
        const double expected = 1.6 + 3.2 * (t >= 3 ? 1.0 : 0.5 - 0.5 * std::cos(std::numbers::pi * t / 3));
        EXPECT_NEAR(y, expected, 1e-9) << t;
        // Where SUMO puts it: the lane whose span holds its centre.
        place = y < 3.2 ? LateralPlace{0, y - 1.6} : LateralPlace{1, y - 4.8};
    }
    EXPECT_TRUE(change.reached());
}

TEST(SpeedTransition, ItsOutcomeIsSharedByItsCopies) {
    // The effect keeps the outcome, the EffectStack a copy that it drives: the effect sees it run.
    const SpeedTransition made({Shape::Linear, Dimension::Time, 1.0}, {SpeedTarget::Kind::Absolute, 20});
    const auto outcome = made.outcome();
    SpeedTransition driven = made;
    for (int k = 0; k < 9; ++k) driven.next(k * 0.1, 0.1, 10, 0);
    EXPECT_FALSE(outcome->reached) << "0.9 s of 1 s";
    EXPECT_DOUBLE_EQ(outcome->target, 20.0);
    driven.next(0.9, 0.1, 19, 0);
    EXPECT_TRUE(outcome->reached) << "the step that ends at 1 s reaches it";
}

TEST(LateralTransition, ReachedIsSharedByItsCopies) {
    const std::vector<double> widths{3.2, 3.2};
    const LateralTransition made({Shape::Linear, Dimension::Time, 0.5}, {1, 0});
    const auto reached = made.reachedFlag();
    LateralTransition driven = made;
    LateralPlace place{0, 0};
    for (int k = 0; k < 4; ++k) place.offset += driven.next(k * 0.1, 0.1, place, widths, 20, 0);
    EXPECT_FALSE(*reached);
    driven.next(0.4, 0.1, place, widths, 20, 0);
    EXPECT_TRUE(*reached);
}

TEST(LateralTransition, MaxLateralAccelerationGivesTheTime) {
    const std::vector<double> widths{3.2};
    // 0.6 m at 0.4 m/s² sinusoidal: T = π sqrt(0.6 / 0.8) = 2.72 s; cubic: sqrt(6 · 0.6 / 0.4) = 3 s.
    auto cubic = LateralTransition::withMaxAcceleration(Shape::Cubic, 0.4, {0, 0.6});
    const double half = cubic.next(0, 1.5, {0, 0}, widths, 10, 0);
    EXPECT_NEAR(half, 0.3, 1e-9);
    auto sine = LateralTransition::withMaxAcceleration(Shape::Sinusoidal, 0.4, {0, 0.6});
    const double t = std::numbers::pi * std::sqrt(0.75);
    EXPECT_NEAR(sine.next(0, t / 2, {0, 0}, widths, 10, 0), 0.3, 1e-9);
}

/// A vehicle for the stack's speed and lateral transitions: takes commands as SUMO would.
class TransitionVehicle : public VehicleController {
public:
    TransitionVehicle() : VehicleController("model") {}
    double speed() const override { return speed_; }
    int speedMode() const override { return speedMode_; }
    void setSpeedMode(int mode) override { speedMode_ = mode; }
    void setSpeed(double mps) override { held_ = mps < 0 ? std::nullopt : std::optional<double>(mps); }
    void slowDown(double mps, double /*seconds*/) override { held_ = mps; }
    double emergencyDecel() const override { return 9; }
    double stepLength() const override { return 1.0; }
    double odometer() const override { return 0; }
    std::string roadId() const override { return "road"; }
    int laneIndex() const override { return 0; }
    double lateralLanePosition() const override { return lateral_; }
    std::vector<double> laneWidths() const override { return {3.2, 3.2}; }
    bool sublaneModel() const override { return sublane_; }
    void changeSublane(double latDist) override { lateral_ += latDist; }
    int laneChangeMode() const override { return laneChangeMode_; }
    void setLaneChangeMode(int mode) override { laneChangeMode_ = mode; }
    double maxSpeedLat() const override { return maxSpeedLat_; }
    void setMaxSpeedLat(double mps) override { maxSpeedLat_ = mps; }
    std::string parameter(const std::string& /*key*/) const override { return accelLat_; }
    void setParameter(const std::string& /*key*/, const std::string& value) override { accelLat_ = value; }

    double speed_ = 10;
    int speedMode_ = 31;
    std::optional<double> held_;
    double lateral_ = 0;
    bool sublane_ = true;
    int laneChangeMode_ = 1621;
    double maxSpeedLat_ = 1.0;
    std::string accelLat_ = "1.0";
};

TEST(EffectStackTransitions, SpeedTransitionCommandsEachStepAndGivesSpeedBack) {
    TransitionVehicle v;
    EffectStack stack(v);
    stack.pushSpeedTransition(1,
                              SpeedTransition({Shape::Linear, Dimension::Time, 4}, {SpeedTarget::Kind::Absolute, 20}));
    EXPECT_TRUE(stack.settling());
    stack.settle(10, kernel::SimTime::fromSeconds(5));
    EXPECT_EQ(v.speedMode_, 64 | 24) << "SUMO's acceleration bounds, safe speed and speed limit would bend the shape";
    EXPECT_DOUBLE_EQ(*v.held_, 12.5);
    stack.settle(12.5, kernel::SimTime::fromSeconds(6));
    EXPECT_DOUBLE_EQ(*v.held_, 15.0);
    stack.remove(1);
    EXPECT_FALSE(v.held_.has_value());
    EXPECT_EQ(v.speedMode_, 31);
    EXPECT_FALSE(stack.settling());
    EXPECT_TRUE(stack.empty());
}

TEST(EffectStackTransitions, AHoldRulesOverASpeedTransition) {
    TransitionVehicle v;
    EffectStack stack(v);
    stack.pushSpeedTransition(1, SpeedTransition({Shape::Step, Dimension::Time, 0}, {SpeedTarget::Kind::Absolute, 20}));
    stack.settle(10, kernel::SimTime::fromSeconds(0));
    stack.pushHold(2, EffectStack::Hold::EmergencyStop);
    EXPECT_EQ(v.speedMode_, 0);
    stack.settle(10, kernel::SimTime::fromSeconds(1));
    EXPECT_DOUBLE_EQ(*v.held_, 0.0) << "braking, not the transition's 20";
    stack.remove(1);  // the transition ends under the emergency stop: its speed mode comes back after
    EXPECT_EQ(v.speedMode_, 0);
    stack.remove(2);
    EXPECT_EQ(v.speedMode_, 31);
    EXPECT_FALSE(v.held_.has_value());

    // With the safe gap SUMO's safe speed stays on; a stop between two commands hands the mode back.

    stack.pushHold(3, EffectStack::Hold::Stop);
    stack.pushSpeedTransition(
        4, SpeedTransition({Shape::Step, Dimension::Time, 0}, {SpeedTarget::Kind::Absolute, 20}, /*safeGap=*/true));
    stack.settle(0, kernel::SimTime::fromSeconds(2));
    EXPECT_DOUBLE_EQ(*v.held_, 0.0);
    EXPECT_EQ(v.speedMode_, 31);
    stack.remove(3);  // the stop ends: the transition commands again from the next settle
    stack.settle(0, kernel::SimTime::fromSeconds(3));
    EXPECT_DOUBLE_EQ(*v.held_, 20.0);
    EXPECT_EQ(v.speedMode_, 64 | 25);
    stack.remove(4);
    EXPECT_EQ(v.speedMode_, 31);
}

TEST(EffectStackTransitions, LateralTransitionMovesAndRestoresTheLateralSettings) {
    TransitionVehicle v;
    EffectStack stack(v);
    stack.pushLateralTransition(1, LateralTransition({Shape::Linear, Dimension::Time, 2}, {0, 0.8}));
    EXPECT_EQ(v.laneChangeMode_, 0);
    EXPECT_GT(v.maxSpeedLat_, 100.0);
    stack.settle(10, kernel::SimTime::fromSeconds(0));
    EXPECT_NEAR(v.lateral_, 0.4, 1e-12);
    stack.settle(10, kernel::SimTime::fromSeconds(1));
    EXPECT_NEAR(v.lateral_, 0.8, 1e-12);
    stack.settle(10, kernel::SimTime::fromSeconds(2));
    EXPECT_NEAR(v.lateral_, 0.8, 1e-12) << "held";
    stack.remove(1);
    EXPECT_EQ(v.laneChangeMode_, 1621);
    EXPECT_DOUBLE_EQ(v.maxSpeedLat_, 1.0);
    EXPECT_EQ(v.accelLat_, "1.0");
    EXPECT_TRUE(stack.empty());
}

TEST(EffectStackTransitions, LateralTransitionNeedsTheSublaneModel) {
    TransitionVehicle v;
    v.sublane_ = false;
    EffectStack stack(v);
    EXPECT_THROW(stack.pushLateralTransition(1, LateralTransition({Shape::Linear, Dimension::Time, 2}, {0, 0.8})),
                 std::runtime_error);
    EXPECT_TRUE(stack.empty());
}

}  // namespace
}  // namespace sbsim::traffic
