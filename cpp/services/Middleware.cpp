#include "sbsim/services/Middleware.h"

#include "sbsim/services/ServiceManager.h"

namespace sbsim::services {

Middleware::Middleware(ServiceManager& manager, std::string vehicleId)
    : kernel::Module(vehicleId + ".middleware"),
      manager_(manager),
      vehicleId_(std::move(vehicleId)),
      controller_(std::make_unique<traffic::VehicleController>(vehicleId_)) {}

void Middleware::host(Service& service, const ServiceSpec& spec) {
    service.middleware_ = this;
    service.spec_ = &spec;
    service.setName(vehicleId_ + "." + spec.type);
    services_.push_back(&service);
}

void Middleware::trigger() {
    // A vehicle departing in the step at a grid time has just been initialized: its first
    // trigger is the next one.
    if (simTime() <= departedAt_) return;
    for (Service* s : services_) s->trigger();
}

void Middleware::handleMessage(kernel::Message& msg) {
    if (auto* delivery = dynamic_cast<Delivery*>(&msg)) {
        manager_.medium().delivered(*delivery->message);
        for (Service* s : services_) s->indicate(*delivery->message);
    } else {
        kernel::Module::handleMessage(msg);
    }
}

void Middleware::signal(const storyboard::StoryboardSignal& signal) {
    for (Service* s : services_) s->receiveSignal(signal);
}

}  // namespace sbsim::services
