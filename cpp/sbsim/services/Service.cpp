#include "sbsim/services/Service.h"

#include <stdexcept>

#include "sbsim/services/Middleware.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::services {

namespace {
Middleware& hostOf(Middleware* m) {
    if (m == nullptr) throw std::logic_error("service is not hosted by a middleware yet");
    return *m;
}
}  // namespace

const std::string& Service::vehicleId() const { return hostOf(middleware_).vehicleId(); }
ServiceVehicle& Service::vehicle() { return hostOf(middleware_).vehicleOf(*this); }
const traffic::VehicleSnapshot& Service::snapshot() const { return hostOf(middleware_).manager().snapshot(); }

std::optional<traffic::VehicleSnapshot::Index> Service::selfIndex() const { return snapshot().indexOf(vehicleId()); }

Eigen::Vector2d Service::position() const { return hostOf(middleware_).position(); }
const facilities::StationFacilities& Service::facilities() const { return hostOf(middleware_).facilities(); }
facilities::StationRegistry& Service::stations() const { return hostOf(middleware_).manager().stations(); }
radio::Medium& Service::medium() const { return hostOf(middleware_).manager().medium(); }

void Service::send(std::unique_ptr<radio::V2xMessage> message) {
    hostOf(middleware_).manager().medium().broadcast(vehicleId(), std::move(message));
}

void Service::listenToAllSignals() { hostOf(middleware_).manager().listenToAllSignals(*this); }

std::optional<kernel::StudyParameters::Value> Service::studyParameter(const std::string& name) const {
    return simulation().parameters().get(name);
}

const ServiceSpec& Service::spec() const {
    if (spec_ == nullptr) throw std::logic_error("service is not hosted by a middleware yet");
    return *spec_;
}

std::optional<std::string> Service::parameter(const std::string& name) const {
    return spec_ == nullptr ? std::nullopt : spec_->parameter(name);
}

double Service::numberParameter(const std::string& name, double fallback) const {
    return spec_ == nullptr ? fallback : spec_->number(name, fallback);
}

}  // namespace sbsim::services
