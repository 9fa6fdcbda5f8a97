#include "sbsim/services/Middleware.h"

#include <stdexcept>

#include "sbsim/services/ServiceManager.h"

namespace sbsim::services {

Middleware::Middleware(ServiceManager& manager, std::string vehicleId)
    : kernel::Module(vehicleId + ".middleware"),
      manager_(manager),
      vehicleId_(std::move(vehicleId)),
      vehicle_(manager.registry().of(vehicleId_)) {}

void Middleware::host(Service& service, const ServiceSpec& spec) {
    service.middleware_ = this;
    service.spec_ = &spec;
    service.setName(vehicleId_ + "." + spec.type);
    services_.push_back(&service);
    vehicles_.push_back(std::make_unique<ServiceVehicle>(vehicle_, manager_.registry()));
}

ServiceVehicle& Middleware::vehicleOf(const Service& service) {
    for (std::size_t k = 0; k < services_.size(); ++k) {
        if (services_[k] == &service) return *vehicles_[k];
    }
    throw std::logic_error("the service is not hosted here");
}

void Middleware::trigger() {
    // A vehicle departing in the step at a grid time has just been initialized: its first
    // trigger is the next one.
    if (simTime() <= departedAt_) return;
    for (Service* s : services_) s->trigger();
}

void Middleware::receive(const radio::V2xMessage& message) {
    for (Service* s : services_) s->indicate(message);
}

void Middleware::signal(const traffic::StoryboardSignal& signal) {
    for (Service* s : services_) s->receiveSignal(signal);
}

}  // namespace sbsim::services
