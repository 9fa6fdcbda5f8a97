#pragma once

#include "sbsim/services/NeedsVehicle.h"
#include "sbsim/services/Service.h"

namespace sbsim::services {

/// Reacts to an emergency vehicle's ClearLaneMessage: a vehicle on the same road but in another
/// lane slows to `speed` m/s (default 25) by capping its max speed, so the emergency vehicle
/// passes safely. Vehicles in the emergency vehicle's own lane are left alone.
class ClearLaneService : public Service, public NeedsVehicle {
public:
    void initialize() override;
    void indicate(const radio::V2xMessage& message) override;
    std::string_view whyVehicle() const override { return "it commands its vehicle"; }

    bool slowed() const { return slowed_; }

private:
    double speed_ = 25;
    bool slowed_ = false;
};

}  // namespace sbsim::services
