#include "sbsim/services/ServiceVehicle.h"

namespace sbsim::services {

ServiceVehicle::ServiceVehicle(std::shared_ptr<traffic::VehicleRegistry::Vehicle> vehicle,
                               traffic::VehicleRegistry& registry)
    : VehicleController(vehicle->controller->id()), vehicle_(std::move(vehicle)), registry_(registry) {}

void ServiceVehicle::replace(std::optional<traffic::EffectStack::Token>& own,
                             const std::function<void(traffic::EffectStack::Token)>& push) {
    const auto old = own;
    own = registry_.newToken();
    push(*own);
    if (old) vehicle_->stack.remove(*old);
}

void ServiceVehicle::setMaxSpeed(double mps) {
    replace(cap_, [&](traffic::EffectStack::Token token) { vehicle_->stack.pushSpeedCap(token, mps); });
}

void ServiceVehicle::end(std::optional<traffic::EffectStack::Token>& own) {
    if (!own) return;
    vehicle_->stack.remove(*own);
    own.reset();
}

void ServiceVehicle::endMaxSpeed() { end(cap_); }

void ServiceVehicle::stop() {
    replace(hold_, [&](traffic::EffectStack::Token token) {
        vehicle_->stack.pushHold(token, traffic::EffectStack::Hold::Stop);
    });
}

void ServiceVehicle::endStop() { end(hold_); }

void ServiceVehicle::holdSpeedFactor(double factor) {
    replace(factor_, [&](traffic::EffectStack::Token token) { vehicle_->stack.pushSpeedFactor(token, factor); });
}

void ServiceVehicle::endSpeedFactor() { end(factor_); }

void ServiceVehicle::holdColor(const traffic::Color& color) {
    replace(color_, [&](traffic::EffectStack::Token token) { vehicle_->stack.pushColor(token, color); });
}

void ServiceVehicle::endColor() { end(color_); }

void ServiceVehicle::changeTarget(const std::string& edge) {
    routeValue_.target = edge;
    replace(route_, [&](traffic::EffectStack::Token token) { vehicle_->stack.pushRoute(token, routeValue_); });
}

void ServiceVehicle::setVia(const std::vector<std::string>& edges) {
    routeValue_.via = edges;
    replace(route_, [&](traffic::EffectStack::Token token) { vehicle_->stack.pushRoute(token, routeValue_); });
}

void ServiceVehicle::endRoute() {
    if (!route_) return;
    vehicle_->stack.remove(*route_);
    route_.reset();
    routeValue_ = {};
}

}  // namespace sbsim::services
