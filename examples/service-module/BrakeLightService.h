#pragma once

#include <sbsim/radio/V2xMessage.h>
#include <sbsim/services/Service.h>

namespace example {

/// "I am braking hard": sent by a vehicle decelerating harder than a threshold.
class BrakeLightMessage : public sbsim::radio::V2xMessage {
public:
    explicit BrakeLightMessage(double deceleration) : deceleration_(deceleration) {}
    std::string_view typeName() const override { return "BrakeLight"; }
    std::size_t byteSize() const override { return 48; }
    double deceleration() const { return deceleration_; }

private:
    double deceleration_;
};

/// An electronic brake light: on every trigger, if the vehicle brakes harder than `threshold`
/// m/s², it warns the vehicles around it; a vehicle that hears a warning from within
/// `react-distance` metres caps its speed at `caution-speed` m/s for `caution-time` seconds
/// (its own timer), then gets its max speed back.
class BrakeLightService : public sbsim::services::Service {
public:
    void initialize() override;
    void trigger() override;
    void indicate(const sbsim::radio::V2xMessage& message) override;
    void handleMessage(sbsim::kernel::Message& msg) override;

private:
    double threshold_ = 3.0;
    double reactDistance_ = 100.0;
    double cautionSpeed_ = 8.0;
    double cautionTime_ = 5.0;
    sbsim::kernel::Message cautionOver_{"caution over"};
};

}  // namespace example
