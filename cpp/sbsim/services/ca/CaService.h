#pragma once

#include <Eigen/Core>
#include <deque>
#include <optional>

#include "sbsim/facilities/Cam.h"
#include "sbsim/services/IndicatedTypes.h"
#include "sbsim/services/NeedsVehicle.h"
#include "sbsim/services/Service.h"
#include "sbsim/services/ca/CamGenerationRules.h"

namespace sbsim::services {

/// ETSI's cooperative awareness basic service (EN 302 637-2) as Artery's CaService: on every
/// middleware trigger it applies CamGenerationRules to the vehicle's current position, speed and
/// heading (with the medium's DCC interval if it models DCC) and sends a CAM when they say so,
/// with the low-frequency container in the first CAM and then at most every 500 ms. Received CAMs
/// go into the station's local dynamic map (the middleware does that for every station).
///
/// Parameters (Artery's names; times in seconds): minInterval (0.1), maxInterval (1),
/// headingDelta (4°), positionDelta (4 m), speedDelta (0.5 m/s), fixedRate (false: the rules;
/// true: every T_GenCamDcc), withDccRestriction (true).
class CaService : public Service, public NeedsVehicle, public IndicatedTypes {
public:
    static constexpr kernel::SimTime kLowFrequencyInterval = kernel::SimTime::fromMilliseconds(500);
    /// None: it only sends (the station's LDM takes the CAMs it hears).
    std::vector<std::string> indicatedTypes() const override { return {}; }

    void initialize() override;
    void trigger() override;
    std::string_view whyVehicle() const override {
        return "its CAMs describe its vehicle's motion (a unit sends CAMs with RsuCaService)";
    }

    const CamGenerationRules& rules() const { return *rules_; }
    std::size_t camsSent() const { return sent_; }

private:
    std::optional<CamGenerationRules> rules_;
    bool dcc_ = true;
    std::optional<kernel::SimTime> lastLowFrequency_;
    std::deque<Eigen::Vector2d> pathHistory_;                        // positions of the last CAMs, newest first
    std::optional<std::pair<kernel::SimTime, double>> lastHeading_;  // for the yaw rate
    std::size_t sent_ = 0;
};

}  // namespace sbsim::services
