#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/LatestWins.h"
#include "sbsim/traffic/Color.h"
#include "sbsim/traffic/VehicleController.h"

namespace sbsim::storyboard {

/// One vehicle's active built-in effects, composed per domain so that the vehicle always behaves
/// as if only the currently active stories had ever acted (Artery's stack restores in the wrong
/// order when stories end out of order):
/// - max speed: the most recently activated cap rules; the live max speed is recorded when the
///   first cap arrives and restored when the last one leaves;
/// - speed hold: the most recently activated Stop or EmergencyStop rules; the speed mode is
///   recorded for an EmergencyStop and restored when handing over to Stop or releasing;
/// - speed factor, type and colour: the most recently activated one rules (LatestWins), the value
///   from before the first comes back after the last. A type brings its own max speed and maps
///   the speed factor onto its own distribution, so a type change under an active cap or factor
///   records the new type's own values and renews the cap and the factor.
/// A command goes to SUMO only when a domain's effective value changes.
class SBSIM_API EffectStack {
public:
    using Token = std::uint64_t;  ///< identifies one effect activation
    enum class Hold { Stop, EmergencyStop };

    explicit EffectStack(traffic::VehicleController& vehicle) : vehicle_(&vehicle) {}

    void pushSpeedCap(Token token, double mps);
    void pushHold(Token token, Hold hold);
    void pushSpeedFactor(Token token, double factor);
    void pushType(Token token, std::string typeId);
    void pushColor(Token token, traffic::Color color);
    /// Removes the activation `token` from whichever domain holds it; unknown tokens are ignored.
    void remove(Token token);
    /// Called each step with the vehicle's speed: an EmergencyStop braking with slowDown() is
    /// turned into a hold once the vehicle stands, since SUMO lets it drive on after slowDown.
    void settle(double speed) {
        if (!holds_.empty()) settleHold(speed);
    }

    bool empty() const {
        return caps_.empty() && holds_.empty() && factors_.empty() && types_.empty() && colors_.empty();
    }
    /// Whether a Stop or EmergencyStop is active (only then does settle() have work).
    bool holding() const { return !holds_.empty(); }
    std::optional<double> effectiveCap() const;
    std::optional<Hold> effectiveHold() const;
    std::optional<double> effectiveSpeedFactor() const { return factors_.effective(); }
    std::optional<std::string> effectiveType() const { return types_.effective(); }
    std::optional<traffic::Color> effectiveColor() const { return colors_.effective(); }

private:
    void settleHold(double speed);
    void applyCap(std::optional<double> before);
    void applyHold(std::optional<Hold> before);
    void applyType(const std::string& typeId);
    std::string ownType() const;

    traffic::VehicleController* vehicle_;
    std::vector<std::pair<Token, double>> caps_;  // activation order
    std::vector<std::pair<Token, Hold>> holds_;   // activation order
    double recordedMaxSpeed_ = 0;
    std::optional<int> recordedSpeedMode_;
    bool emergencyHeld_ = false;  // the EmergencyStop's vehicle stands and is held at 0
    LatestWins<double> factors_;
    LatestWins<std::string> types_;
    LatestWins<traffic::Color> colors_;
};

}  // namespace sbsim::storyboard
