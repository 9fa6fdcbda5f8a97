#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "sbsim/facilities/Denm.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/traffic/StoryboardSignal.h"

namespace sbsim::services {

class DenService;
struct ServiceSpec;

/// One DEN use case of a DenService (Artery's den::UseCase and SuspendableUseCase): checked on
/// every trigger, told of the storyboard's signals and of received DENMs; it decides when its
/// event starts (and, where Artery leaves it out, when it ends) and sends through the service.
class SBSIM_API UseCase {
public:
    virtual ~UseCase() = default;

    /// Called once by the service, before initialize().
    void attach(DenService& service, const ServiceSpec& spec);
    virtual void initialize() {}
    /// Every middleware trigger.
    virtual void check() {}
    /// A DENM received (inside its destination area), after the memory took it in.
    virtual void indicate(const facilities::Denm& /*denm*/) {}
    /// A storyboard signal for this vehicle.
    virtual void handleSignal(const traffic::StoryboardSignal& /*signal*/) {}

protected:
    DenService& service() const { return *service_; }
    /// A number from the <usecase> element's attributes, else `fallback`.
    double number(std::string_view name, double fallback) const;
    /// A duration from the attributes, else `fallback`, within ServiceSpec::duration's bounds.
    kernel::SimTime duration(std::string_view name, double fallback) const;
    std::optional<std::string> text(std::string_view name) const;

    /// Artery's detection blocking: after blockDetection(), isDetectionBlocked() is true until the
    /// blocking interval passed.
    void setDetectionBlockingInterval(kernel::SimTime interval) { blocking_ = interval; }
    bool isDetectionBlocked();
    void blockDetection();

    /// A new event at the vehicle's position now: a fresh action id, detection and reference
    /// time now, destination a circle of `area` m around the vehicle.
    facilities::DenmContent skeleton(double area) const;

private:
    DenService* service_ = nullptr;
    const ServiceSpec* spec_ = nullptr;
    kernel::SimTime blocking_;
    std::optional<kernel::SimTime> blockedSince_;
};

}  // namespace sbsim::services
