#pragma once

#include <Eigen/Core>
#include <optional>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::services {

/// The station's state the CAM rules compare with the last CAM's.
struct CamDynamics {
    Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< m
    double speed = 0;                                    ///< m/s
    double heading = 0;                                  ///< degrees
};

/// The rules' constants, named as Artery's CaService parameters.
struct SBSIM_API CamRuleSettings {
    kernel::SimTime minInterval = kernel::SimTime::fromMilliseconds(100);   ///< T_GenCamMin
    kernel::SimTime maxInterval = kernel::SimTime::fromMilliseconds(1000);  ///< T_GenCamMax
    double headingDelta = 4;                                                ///< degrees
    double positionDelta = 4;                                               ///< m
    double speedDelta = 0.5;                                                ///< m/s
    bool fixedRate = false;    ///< send every T_GenCamDcc whatever the dynamics
    int lowDynamicsLimit = 3;  ///< sends by T_GenCam in a row before T_GenCam is Max again
};

/// EN 302 637-2's CAM generation rules (section 6.1.3), as Artery's CaService applies them on
/// every middleware trigger. With T_GenCamDcc = the DCC interval clamped to [Min, Max] (Min
/// without DCC): once T_GenCamDcc passed since the last CAM, a CAM goes out if the heading changed
/// by more than headingDelta (compared across 0°/360°), the position by more than positionDelta or
/// the speed by more than speedDelta — then T_GenCam becomes min(elapsed, Max) — or else if
/// T_GenCam passed; after lowDynamicsLimit such sends in a row T_GenCam is Max again. T_GenCam
/// starts at Max. The first check sends (there is no last CAM to compare with).
class SBSIM_API CamGenerationRules {
public:
    enum class Reason { None, First, FixedRate, Dynamics, Timeout };

    explicit CamGenerationRules(CamRuleSettings settings = {});

    /// Whether a CAM goes out at `now` with the station at `current`; if so, it is noted as the
    /// last CAM. `dccInterval`: what the channel's congestion control allows now, if modelled.
    Reason check(kernel::SimTime now, const CamDynamics& current, std::optional<kernel::SimTime> dccInterval);

    const CamRuleSettings& settings() const { return settings_; }
    kernel::SimTime genCam() const { return genCam_; }  ///< T_GenCam
    /// T_GenCamDcc for a DCC interval (or none).
    kernel::SimTime genCamDcc(std::optional<kernel::SimTime> dccInterval) const;
    /// The angle between two headings (degrees), in [0, 180].
    static double headingDifference(double a, double b);

private:
    void sent(kernel::SimTime now, const CamDynamics& current);

    CamRuleSettings settings_;
    kernel::SimTime genCam_;
    int lowDynamicsCount_ = 0;
    std::optional<kernel::SimTime> lastTime_;
    CamDynamics last_;
};

}  // namespace sbsim::services
