#pragma once

#include <optional>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/services/Service.h"

namespace sbsim::services {

/// Artery's RsuCaService: a roadside unit's CAMs, at a fixed interval whatever happens around it
/// (no generation rules: the unit does not move), checked on every middleware trigger like
/// Artery's, so the first goes out at the unit's first trigger. Station type roadSideUnit, its
/// fixed position, speed 0, no low-frequency container (Cam::kRoadSideUnitBytes).
///
/// Parameter (Artery's name): generationInterval (1 s).
class RsuCaService : public Service {
public:
    void initialize() override;
    void trigger() override;

    kernel::SimTime generationInterval() const { return interval_; }
    std::size_t camsSent() const { return sent_; }

private:
    kernel::SimTime interval_ = kernel::SimTime::fromSeconds(1);
    std::optional<kernel::SimTime> last_;
    std::size_t sent_ = 0;
};

}  // namespace sbsim::services
