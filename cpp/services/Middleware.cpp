#include "services/Middleware.h"

#include "services/ServiceManager.h"

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

void Middleware::initialize() {
    // Triggers sit on the interval's grid (the next multiple after now), so all vehicles'
    // services run at the same instants, in departure order.
    const kernel::SimTime interval = manager_.interval();
    const kernel::SimTime next = interval * (simTime() / interval + 1);
    scheduleAt(next, triggerTimer_);
}

void Middleware::handleMessage(kernel::Message& msg) {
    if (&msg == &triggerTimer_) {
        scheduleAfter(manager_.interval(), triggerTimer_);
        for (Service* s : services_) s->trigger();
    } else if (auto* delivery = dynamic_cast<Delivery*>(&msg)) {
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
