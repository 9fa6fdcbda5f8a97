// Effect composition against a model: for every activation order and every removal order of
// 3 and 4 effects on one vehicle, after each step the vehicle must be exactly as if only the
// effects still active had ever acted, and SUMO must be commanded only when a domain changes.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/traffic/EffectStack.h"

namespace sbsim::traffic {
namespace {

kernel::SimTime SimTimeOf(double s) { return kernel::SimTime::fromSeconds(s); }

constexpr double kOwnMaxSpeed = 33.0;
constexpr int kOwnSpeedMode = 31;
constexpr double kSpeed = 12.0;
constexpr double kEmergencyDecel = 9.0;
constexpr double kOwnSpeedFactor = 1.1;
const std::string kOwnType = "car";
constexpr Color kOwnColor{1, 2, 3, 255};
constexpr int kOwnLane = 1;
constexpr int kRoadLanes = 3;
const std::string kOwnDestination = "home";
const std::string kUnreachable = "island";  // an edge SUMO finds no route to

/// Each type's own max speed: a new type brings its own, as in SUMO.
double typeMaxSpeed(const std::string& type) {
    static const std::map<std::string, double> table{{"car", kOwnMaxSpeed}, {"truck", 25.0}, {"bus", 20.0}};
    return table.at(type);
}

/// Each type's speed factor distribution (mean, deviation): SUMO maps a vehicle's factor from the
/// old type's onto the new type's when the type changes.
double mapSpeedFactor(double factor, const std::string& from, const std::string& to) {
    static const std::map<std::string, std::pair<double, double>> table{
        {"car", {1.0, 0.1}}, {"truck", {0.9, 0.05}}, {"bus", {0.8, 0.2}}};
    const auto [oldMu, oldDev] = table.at(from.substr(0, from.find('@')));  // "<type>@<id>": SUMO's copy
    const auto [newMu, newDev] = table.at(to);
    return newMu + (factor - oldMu) / oldDev * newDev;
}

/// A vehicle that behaves like SUMO's for the commands the stack sends, and counts them.
class ModelVehicle : public VehicleController {
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
    std::string typeId() const override { return type_; }
    double speedFactor() const override { return speedFactor_; }
    Color color() const override { return color_; }
    void setSpeedFactor(double factor) override {
        speedFactor_ = factor;
        ++commands;
    }
    void setType(const std::string& type) override {
        speedFactor_ = mapSpeedFactor(speedFactor_, type_, type);
        type_ = type;
        maxSpeed_ = typeMaxSpeed(type);  // a per-vehicle max speed is lost with the old type
        ++commands;
    }
    void setColor(const Color& color) override {
        color_ = color;
        ++commands;
    }
    std::string roadId() const override { return road_; }
    int laneCount() const override { return kRoadLanes; }
    int laneIndex() const override { return kOwnLane; }
    void changeLane(int index, double seconds) override {
        laneCommand_ = {index, seconds};
        ++commands;
    }
    std::vector<std::string> route() const override { return {road_, destination_}; }
    std::vector<std::string> via() const override { return via_; }
    void setVia(const std::vector<std::string>& edges) override {
        via_ = edges;
        ++commands;
    }
    void changeTarget(const std::string& edge) override {
        ++commands;
        if (edge == kUnreachable) throw CommandRefused("no connection to 'island'");
        destination_ = edge;
        routedVia_ = via_;
    }

    double speedFactor_ = kOwnSpeedFactor;
    std::string type_ = kOwnType;
    Color color_ = kOwnColor;
    double maxSpeed_ = kOwnMaxSpeed;
    int speedMode_ = kOwnSpeedMode;
    std::optional<double> held_;
    std::optional<double> slowingTo_;
    double slowDownSeconds = 0;
    std::string road_ = "road";
    std::optional<std::pair<int, double>> laneCommand_;  // the last changeLane: index, seconds
    std::string destination_ = kOwnDestination;
    std::vector<std::string> via_;
    std::vector<std::string> routedVia_;  // the via edges of the last routing
    int commands = 0;
};

struct Spec {
    enum Kind { Cap, Stop, EmergencyStop, Factor, Type, Paint, Lane, Route } kind;
    double cap = 0;         // also the factor, the red of a Paint and the lane
    std::string type = {};  // also a Route's target
    std::vector<std::string> via = {};
    Color color() const { return {static_cast<std::uint8_t>(cap), 0, 0, 255}; }
    std::string label() const {
        switch (kind) {
            case Cap:
                return "cap" + std::to_string(static_cast<int>(cap));
            case Stop:
                return "stop";
            case EmergencyStop:
                return "estop";
            case Factor:
                return "factor" + std::to_string(cap);
            case Type:
                return "type:" + type;
            case Paint:
                return "paint" + std::to_string(static_cast<int>(cap));
            case Lane:
                return "lane" + std::to_string(static_cast<int>(cap));
            case Route:
                return "route:" + (type.empty() ? "via " + via.front() : type);
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
        case Spec::Factor:
            stack.pushSpeedFactor(token, s.cap);
            break;
        case Spec::Type:
            stack.pushType(token, s.type);
            break;
        case Spec::Paint:
            stack.pushColor(token, s.color());
            break;
        case Spec::Lane:
            stack.pushLane(token, static_cast<int>(s.cap));
            break;
        case Spec::Route:
            stack.pushRoute(token, {s.type.empty() ? std::nullopt : std::optional<std::string>(s.type), s.via});
            break;
    }
}

/// The effective value of each domain.
struct Effective {
    std::optional<double> cap;
    std::optional<Spec::Kind> hold;
    std::optional<double> factor;
    std::optional<std::string> type;
    std::optional<double> paint;
    std::optional<int> lane;
    std::optional<std::pair<std::string, std::vector<std::string>>> route;  // target ("": own), via
    bool operator==(const Effective&) const = default;
};

/// The model: in each domain the latest of the active effects (activation order) rules.
Effective effective(const std::vector<Spec>& active) {
    Effective e;
    for (const Spec& s : active) {
        switch (s.kind) {
            case Spec::Cap:
                e.cap = s.cap;
                break;
            case Spec::Stop:
            case Spec::EmergencyStop:
                e.hold = s.kind;
                break;
            case Spec::Factor:
                e.factor = s.cap;
                break;
            case Spec::Type:
                e.type = s.type;
                break;
            case Spec::Paint:
                e.paint = s.cap;
                break;
            case Spec::Lane:
                e.lane = static_cast<int>(s.cap);
                break;
            case Spec::Route:
                e.route = {s.type, s.via};
                break;
        }
    }
    return e;
}

/// What the vehicle must look like with `active` (activation order) in force.
void expectState(const ModelVehicle& v, const std::vector<Spec>& active, const std::string& context) {
    const Effective e = effective(active);
    const auto& cap = e.cap;
    const auto& hold = e.hold;
    const std::string type = e.type.value_or(kOwnType);
    EXPECT_EQ(v.type_, type) << context;
    EXPECT_DOUBLE_EQ(v.maxSpeed_, cap.value_or(typeMaxSpeed(type))) << context;
    EXPECT_NEAR(v.speedFactor_, e.factor.value_or(mapSpeedFactor(kOwnSpeedFactor, kOwnType, type)), 1e-12) << context;
    const Color paint = e.paint ? Spec{Spec::Paint, *e.paint, {}}.color() : kOwnColor;
    EXPECT_EQ(v.color_, paint) << context;
    if (e.lane) {
        const std::pair<int, double> held{std::min(*e.lane, kRoadLanes - 1), EffectStack::kLaneHoldSeconds};
        EXPECT_EQ(v.laneCommand_, held) << context;
    } else {
        // Never held, or released: a command for no time, to the lane it is on.
        const std::pair<int, double> released{kOwnLane, 0.0};
        EXPECT_TRUE(!v.laneCommand_ || v.laneCommand_ == released) << context << ": lane still held";
    }
    if (e.route && e.route->first != kUnreachable) {
        EXPECT_EQ(v.destination_, e.route->first.empty() ? kOwnDestination : e.route->first) << context;
        EXPECT_EQ(v.via_, e.route->second) << context;
        EXPECT_EQ(v.routedVia_, e.route->second) << context;
    } else if (!e.route) {
        EXPECT_EQ(v.destination_, kOwnDestination) << context;
        EXPECT_TRUE(v.via_.empty()) << context;
        EXPECT_TRUE(v.routedVia_.empty()) << context;
    }
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

void runAllOrders(const std::vector<Spec>& specs, const EffectStack::Warn& warn = {}) {
    std::vector<std::size_t> activation(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i) activation[i] = i;
    int cases = 0;
    do {
        std::vector<std::size_t> removal = activation;
        std::sort(removal.begin(), removal.end());
        do {
            ModelVehicle vehicle;
            EffectStack stack(vehicle, warn);
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
                if (effective(activeSpecs()) == before) {
                    EXPECT_EQ(vehicle.commands, commandsBefore) << context << ": needless command";
                }
            }
            context += " | remove";
            for (const std::size_t i : removal) {
                const auto before = effective(activeSpecs());
                const int commandsBefore = vehicle.commands;
                stack.remove(i + 1);
                active.erase(std::find(active.begin(), active.end(), i));
                context += " " + specs[i].label();
                expectState(vehicle, activeSpecs(), context);
                if (effective(activeSpecs()) == before) {
                    EXPECT_EQ(vehicle.commands, commandsBefore) << context << ": needless command";
                }
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

TEST(EffectStack, ThreeSpeedFactorsInEveryOrder) {
    runAllOrders({{Spec::Factor, 0.5}, {Spec::Factor, 0.8}, {Spec::Factor, 0.5}});
}

TEST(EffectStack, ThreeTypesInEveryOrder) {
    runAllOrders({{Spec::Type, 0, "truck"}, {Spec::Type, 0, "bus"}, {Spec::Type, 0, "truck"}});
}

TEST(EffectStack, ThreeColoursInEveryOrder) {
    runAllOrders({{Spec::Paint, 200}, {Spec::Paint, 100}, {Spec::Paint, 50}});
}

TEST(EffectStack, TypesUnderACapKeepTheCapInEveryOrder) {
    // A type brings its own max speed: a cap must survive type changes, and when the cap ends
    // the max speed of the type then in force comes back.
    runAllOrders({{Spec::Cap, 10}, {Spec::Type, 0, "truck"}, {Spec::Type, 0, "bus"}});
}

TEST(EffectStack, TypesUnderASpeedFactorKeepItInEveryOrder) {
    runAllOrders({{Spec::Factor, 0.5}, {Spec::Type, 0, "truck"}, {Spec::Type, 0, "bus"}});
}

TEST(EffectStack, FactorTypeColourCapAndStopInEveryOrder) {
    runAllOrders({{Spec::Factor, 0.7}, {Spec::Type, 0, "bus"}, {Spec::Paint, 9}, {Spec::Cap, 12}, {Spec::Stop}});
}

TEST(EffectStack, ThreeLanesInEveryOrder) { runAllOrders({{Spec::Lane, 0}, {Spec::Lane, 2}, {Spec::Lane, 0}}); }

TEST(EffectStack, ThreeRoutesInEveryOrder) {
    runAllOrders({{Spec::Route, 0, "west"}, {Spec::Route, 0, "", {"bridge", "tunnel"}}, {Spec::Route, 0, "east"}});
}

TEST(EffectStack, LaneRouteCapAndColourInEveryOrder) {
    runAllOrders({{Spec::Lane, 1}, {Spec::Route, 0, "west"}, {Spec::Cap, 12}, {Spec::Paint, 9}});
}

TEST(EffectStack, ARouteSumoCannotFindIsAWarningInEveryOrder) {
    // The vehicle keeps the route it has while the unreachable target rules; the others and the
    // own destination still come back.
    int warnings = 0;
    runAllOrders({{Spec::Route, 0, kUnreachable}, {Spec::Route, 0, "west"}, {Spec::Lane, 0}},
                 [&](const std::string& message) {
                     EXPECT_NE(message.find("island"), std::string::npos) << message;
                     ++warnings;
                 });
    EXPECT_GT(warnings, 0);
}

TEST(EffectStack, ALaneBeyondTheRoadsLanesIsItsLeftmost) {
    ModelVehicle v;
    EffectStack stack(v);
    stack.pushLane(1, 7);
    EXPECT_EQ(v.laneCommand_, (std::pair<int, double>{kRoadLanes - 1, EffectStack::kLaneHoldSeconds}));
}

TEST(EffectStack, TheLaneIsRenewedEachStepOnlyWhileActive) {
    ModelVehicle v;
    EffectStack stack(v);
    EXPECT_FALSE(stack.settling());
    stack.pushLane(1, 0);
    EXPECT_TRUE(stack.settling());
    for (int step = 1; step <= 3; ++step) {
        v.laneCommand_.reset();
        stack.settle(kSpeed);
        EXPECT_EQ(v.laneCommand_, (std::pair<int, double>{0, EffectStack::kLaneHoldSeconds})) << "step " << step;
    }
    v.road_ = ":junction_0";  // SUMO's internal road: the last command stands
    v.laneCommand_.reset();
    stack.settle(kSpeed);
    EXPECT_FALSE(v.laneCommand_.has_value());
    v.road_ = "next";
    stack.settle(kSpeed);
    EXPECT_TRUE(v.laneCommand_.has_value());
    stack.remove(1);
    EXPECT_EQ(v.laneCommand_, (std::pair<int, double>{kOwnLane, 0.0}));
    EXPECT_FALSE(stack.settling()) << "no lane: settle() has nothing to renew";
}

TEST(EffectStack, TheTypeComingBackIsTheOneSumosPrivateCopyWasMadeOf) {
    ModelVehicle v;
    v.type_ = "car@model";  // what SUMO reports after setMaxSpeed made the vehicle its own type
    EffectStack stack(v);
    stack.pushType(1, "truck");
    stack.remove(1);
    EXPECT_EQ(v.type_, "car");
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

TEST(EffectStack, AGradualCapSlowsDownOverItsTimeThenCaps) {
    ModelVehicle v;  // at kSpeed = 12 m/s
    EffectStack stack(v);
    stack.pushSpeedCap(1, 5, 10);
    ASSERT_TRUE(v.slowingTo_.has_value());
    EXPECT_DOUBLE_EQ(*v.slowingTo_, 5.0);
    EXPECT_DOUBLE_EQ(v.slowDownSeconds, 10.0);
    EXPECT_DOUBLE_EQ(v.maxSpeed_, kOwnMaxSpeed) << "no cap before the ramp has run";
    EXPECT_TRUE(stack.settling());
    stack.settle(12, SimTimeOf(100));  // the step the story activated in
    stack.settle(9, SimTimeOf(105));
    EXPECT_DOUBLE_EQ(v.maxSpeed_, kOwnMaxSpeed);
    stack.settle(5, SimTimeOf(110));
    EXPECT_DOUBLE_EQ(v.maxSpeed_, 5.0);
    EXPECT_FALSE(stack.settling());
    stack.remove(1);
    EXPECT_DOUBLE_EQ(v.maxSpeed_, kOwnMaxSpeed);
}

TEST(EffectStack, AGradualCapComposesLikeAPlainOne) {
    ModelVehicle v;
    EffectStack stack(v);
    stack.pushSpeedCap(1, 5, 10);
    stack.settle(12, SimTimeOf(0));
    stack.pushSpeedCap(2, 8);  // the latest rules at once; the ramp ends
    EXPECT_DOUBLE_EQ(v.maxSpeed_, 8.0);
    EXPECT_FALSE(v.slowingTo_.has_value()) << "setSpeed(-1) handed the speed back to SUMO";
    stack.remove(2);  // back to the gradual cap: ramps again from the current speed
    EXPECT_DOUBLE_EQ(*v.slowingTo_, 5.0);
    stack.remove(1);
    EXPECT_DOUBLE_EQ(v.maxSpeed_, kOwnMaxSpeed);
}

TEST(EffectStack, AGradualCapBelowTheSpeedIsSetAtOnce) {
    ModelVehicle v;  // 12 m/s: nothing to slow down from
    EffectStack stack(v);
    stack.pushSpeedCap(1, 20, 10);
    EXPECT_FALSE(v.slowingTo_.has_value());
    EXPECT_DOUBLE_EQ(v.maxSpeed_, 20.0);
}

}  // namespace
}  // namespace sbsim::traffic
