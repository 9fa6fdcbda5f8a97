#include "sbsim/services/den/UseCase.h"

#include "sbsim/services/ServicesConfig.h"
#include "sbsim/services/den/DenService.h"

namespace sbsim::services {

void UseCase::attach(DenService& service, const ServiceSpec& spec) {
    service_ = &service;
    spec_ = &spec;
}

double UseCase::number(std::string_view name, double fallback) const { return spec_->number(name, fallback); }

kernel::SimTime UseCase::duration(std::string_view name, double fallback) const {
    return spec_->duration(name, fallback);
}

std::optional<std::string> UseCase::text(std::string_view name) const { return spec_->parameter(name); }

bool UseCase::isDetectionBlocked() {
    if (!blockedSince_) return false;
    if (*blockedSince_ + blocking_ < service_->now()) {
        blockedSince_.reset();
        return false;
    }
    return true;
}

void UseCase::blockDetection() { blockedSince_ = service_->now(); }

facilities::DenmContent UseCase::skeleton(double area) const {
    facilities::DenmContent denm;
    denm.action = service_->requestActionId();
    denm.detectionTime = service_->now();
    denm.referenceTime = denm.detectionTime;
    denm.eventPosition = service_->stationPosition();
    denm.destination = {denm.eventPosition, area};
    return denm;
}

}  // namespace sbsim::services
