// Effect composition against a model: for every activation order and every removal order of
// 3 and 4 effects on one vehicle, after each step the vehicle must be exactly as if only the
// effects still active had ever acted, and SUMO must be commanded only when a domain changes.

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/storyboard/EffectStack.h"

namespace sbsim::storyboard {
namespace {

constexpr double kOwnMaxSpeed = 33.0;
constexpr int kOwnSpeedMode = 31;
constexpr double kSpeed = 12.0;
constexpr double kEmergencyDecel = 9.0;

/// A vehicle that behaves like SUMO's for the commands the stack sends, and counts them.
class ModelVehicle : public traffic::VehicleController {
public:
    ModelVehicle() : VehicleController("model") {}

    double speed() const override { return kSpeed; }
    double maxSpeed() const override { return maxSpeed_; }
    double emergencyDecel() const override { return kEmergencyDecel; }
    int speedMode() const override { return speedMode_; }

    void setMaxSpeed(double mps) override {
        maxSpeed_ = mps;
        ++commands;
    }
    void setSpeed(double mps) override {
        // SUMO: a negative speed hands control back, anything else holds the vehicle there.
        held_ = mps < 0 ? std::nullopt : std::optional<double>(mps);
        slowingTo_.reset();
        ++commands;
    }
    void slowDown(double mps, double seconds) override {
        slowingTo_ = mps;
        slowDownSeconds = seconds;
        held_.reset();
        ++commands;
    }
    void setSpeedMode(int mode) override {
        speedMode_ = mode;
        ++commands;
    }

    double maxSpeed_ = kOwnMaxSpeed;
    int speedMode_ = kOwnSpeedMode;
    std::optional<double> held_;
    std::optional<double> slowingTo_;
    double slowDownSeconds = 0;
    int commands = 0;
};

struct Spec {
    enum Kind { Cap, Stop, EmergencyStop } kind;
    double cap = 0;
    std::string label() const {
        switch (kind) {
            case Cap:
                return "cap" + std::to_string(static_cast<int>(cap));
            case Stop:
                return "stop";
            case EmergencyStop:
                return "estop";
        }
        return "?";
    }
};

void push(EffectStack& stack, const Spec& s, EffectStack::Token token) {
    switch (s.kind) {
        case Spec::Cap:
            stack.pushSpeedCap(token, s.cap);
            break;
        case Spec::Stop:
            stack.pushHold(token, EffectStack::Hold::Stop);
            break;
        case Spec::EmergencyStop:
            stack.pushHold(token, EffectStack::Hold::EmergencyStop);
            break;
    }
}

/// The model: the latest cap and the latest hold of the active effects (activation order) rule.
std::pair<std::optional<double>, std::optional<Spec::Kind>> effective(const std::vector<Spec>& active) {
    std::optional<double> cap;
    std::optional<Spec::Kind> hold;
    for (const Spec& s : active) {
        if (s.kind == Spec::Cap)
            cap = s.cap;
        else
            hold = s.kind;
    }
    return {cap, hold};
}

/// What the vehicle must look like with `active` (activation order) in force.
void expectState(const ModelVehicle& v, const std::vector<Spec>& active, const std::string& context) {
    const auto [cap, hold] = effective(active);
    EXPECT_DOUBLE_EQ(v.maxSpeed_, cap.value_or(kOwnMaxSpeed)) << context;
    if (!hold) {
        EXPECT_FALSE(v.held_.has_value()) << context << ": vehicle still held";
        EXPECT_FALSE(v.slowingTo_.has_value()) << context << ": vehicle still braking";
        EXPECT_EQ(v.speedMode_, kOwnSpeedMode) << context;
    } else if (*hold == Spec::Stop) {
        ASSERT_TRUE(v.held_.has_value()) << context << ": Stop active but vehicle not held";
        EXPECT_DOUBLE_EQ(*v.held_, 0.0) << context;
        EXPECT_EQ(v.speedMode_, kOwnSpeedMode) << context << ": Stop keeps the vehicle's own speed mode";
    } else {
        ASSERT_TRUE(v.slowingTo_.has_value()) << context << ": EmergencyStop active but vehicle not braking";
        EXPECT_DOUBLE_EQ(*v.slowingTo_, 0.0) << context;
        EXPECT_DOUBLE_EQ(v.slowDownSeconds, kSpeed / kEmergencyDecel) << context;
        EXPECT_EQ(v.speedMode_, 0) << context;
    }
}

void runAllOrders(const std::vector<Spec>& specs) {
    std::vector<std::size_t> activation(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i) activation[i] = i;
    int cases = 0;
    do {
        std::vector<std::size_t> removal = activation;
        std::sort(removal.begin(), removal.end());
        do {
            ModelVehicle vehicle;
            EffectStack stack(vehicle);
            std::vector<std::size_t> active;  // indices into specs, activation order
            const auto activeSpecs = [&] {
                std::vector<Spec> out;
                for (const std::size_t k : active) out.push_back(specs[k]);
                return out;
            };
            std::string context = "activate";
            for (const std::size_t i : activation) {
                const auto before = effective(activeSpecs());
                const int commandsBefore = vehicle.commands;
                push(stack, specs[i], i + 1);
                active.push_back(i);
                context += " " + specs[i].label();
                expectState(vehicle, activeSpecs(), context);
                if (effective(activeSpecs()) == before)
                    EXPECT_EQ(vehicle.commands, commandsBefore) << context << ": needless command";
            }
            context += " | remove";
            for (const std::size_t i : removal) {
                const auto before = effective(activeSpecs());
                const int commandsBefore = vehicle.commands;
                stack.remove(i + 1);
                active.erase(std::find(active.begin(), active.end(), i));
                context += " " + specs[i].label();
                expectState(vehicle, activeSpecs(), context);
                if (effective(activeSpecs()) == before)
                    EXPECT_EQ(vehicle.commands, commandsBefore) << context << ": needless command";
            }
            EXPECT_TRUE(stack.empty());
            ++cases;
            if (testing::Test::HasFailure()) return;  // one failing order says enough
        } while (std::next_permutation(removal.begin(), removal.end()));
    } while (std::next_permutation(activation.begin(), activation.end()));
    const int n = static_cast<int>(specs.size());
    int factorial = 1;
    for (int k = 2; k <= n; ++k) factorial *= k;
    EXPECT_EQ(cases, factorial * factorial);
}

TEST(EffectStack, TwoCapsAndAStopInEveryOrder) { runAllOrders({{Spec::Cap, 10}, {Spec::Cap, 20}, {Spec::Stop}}); }

TEST(EffectStack, TwoStopsAndAnEmergencyStopInEveryOrder) {
    runAllOrders({{Spec::Stop}, {Spec::Stop}, {Spec::EmergencyStop}});
}

TEST(EffectStack, CapsStopAndEmergencyStopInEveryOrder) {
    runAllOrders({{Spec::Cap, 10}, {Spec::Cap, 20}, {Spec::Stop}, {Spec::EmergencyStop}});
}

TEST(EffectStack, ThreeCapsAndAStopInEveryOrder) {
    runAllOrders({{Spec::Cap, 5}, {Spec::Cap, 15}, {Spec::Cap, 25}, {Spec::Stop}});
}

TEST(EffectStack, OneStopEndingNeverReleasesAVehicleAnotherStopHolds) {
    ModelVehicle v;
    EffectStack stack(v);
    stack.pushHold(1, EffectStack::Hold::Stop);
    stack.pushHold(2, EffectStack::Hold::Stop);
    stack.remove(1);
    ASSERT_TRUE(v.held_.has_value());
    EXPECT_DOUBLE_EQ(*v.held_, 0.0);
    stack.remove(2);
    EXPECT_FALSE(v.held_.has_value());
}

TEST(EffectStack, MaxSpeedIsRecordedWhenTheFirstCapArrives) {
    ModelVehicle v;
    EffectStack stack(v);
    v.maxSpeed_ = 27.0;  // changed by someone else before any cap
    stack.pushSpeedCap(1, 5);
    stack.pushSpeedCap(2, 8);
    stack.remove(2);
    EXPECT_DOUBLE_EQ(v.maxSpeed_, 5.0);
    stack.remove(1);
    EXPECT_DOUBLE_EQ(v.maxSpeed_, 27.0);
}

TEST(EffectStack, EmergencyStopOfAStandingVehicleHoldsItWithSetSpeed) {
    class Standing : public ModelVehicle {
        double speed() const override { return 0.0; }
    } v;
    EffectStack stack(v);
    stack.pushHold(1, EffectStack::Hold::EmergencyStop);
    ASSERT_TRUE(v.held_.has_value());
    EXPECT_DOUBLE_EQ(*v.held_, 0.0);
    EXPECT_EQ(v.speedMode_, 0);
    stack.remove(1);
    EXPECT_EQ(v.speedMode_, kOwnSpeedMode);
    EXPECT_FALSE(v.held_.has_value());
}

TEST(EffectStack, AnEmergencyStopHoldsTheVehicleOnceItStands) {
    ModelVehicle v;
    EffectStack stack(v);
    stack.pushHold(1, EffectStack::Hold::EmergencyStop);
    ASSERT_TRUE(v.slowingTo_.has_value());
    stack.settle(6.0);  // still braking: nothing to do
    EXPECT_FALSE(v.held_.has_value());
    const int commands = v.commands;
    stack.settle(0.0);
    ASSERT_TRUE(v.held_.has_value());
    EXPECT_DOUBLE_EQ(*v.held_, 0.0);
    EXPECT_EQ(v.speedMode_, 0) << "still an emergency stop: SUMO's checks stay off";
    stack.settle(0.0);
    EXPECT_EQ(v.commands, commands + 1) << "held once, not every step";
    stack.remove(1);
    EXPECT_FALSE(v.held_.has_value());
    EXPECT_EQ(v.speedMode_, kOwnSpeedMode);
}

TEST(EffectStack, SettleLeavesAPlainStopAlone) {
    ModelVehicle v;
    EffectStack stack(v);
    stack.pushHold(1, EffectStack::Hold::Stop);
    const int commands = v.commands;
    stack.settle(0.0);
    EXPECT_EQ(v.commands, commands);
}

TEST(EffectStack, UnknownTokensAreIgnored) {
    ModelVehicle v;
    EffectStack stack(v);
    stack.pushSpeedCap(1, 5);
    const int commands = v.commands;
    stack.remove(42);
    EXPECT_EQ(v.commands, commands);
    EXPECT_DOUBLE_EQ(v.maxSpeed_, 5.0);
}

}  // namespace
}  // namespace sbsim::storyboard
