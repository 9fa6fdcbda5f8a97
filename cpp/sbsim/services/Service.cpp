#include "sbsim/services/Service.h"

#include <fmt/format.h>

#include <stdexcept>

#include "sbsim/services/Middleware.h"
#include "sbsim/services/ServiceError.h"
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

std::optional<traffic::VehicleSnapshot::Index> Service::selfIndex() const { return hostOf(middleware_).selfIndex(); }

bool Service::roadsideUnit() const { return hostOf(middleware_).stationary(); }
Eigen::Vector2d Service::position() const { return hostOf(middleware_).position(); }
const facilities::StationFacilities& Service::facilities() const { return hostOf(middleware_).facilities(); }
facilities::StationRegistry& Service::stations() const { return hostOf(middleware_).manager().stations(); }
radio::Medium& Service::medium() const { return hostOf(middleware_).manager().medium(); }

void Service::send(std::unique_ptr<radio::V2xMessage> message) { hostOf(middleware_).send(std::move(message)); }

void Service::failed() {
    const std::string where =
        fmt::format("service {} on vehicle {} at t={} s", spec_ == nullptr ? name() : spec_->type,
                    middleware_ == nullptr ? std::string("?") : middleware_->vehicleId(), simTime().str());
    try {
        throw;
    } catch (const ServiceError&) {
        throw;
    } catch (const ServicesConfigError&) {
        throw;
    } catch (const std::exception& e) {
        throw ServiceError(fmt::format("{}: {}", where, e.what()));
    } catch (...) {
        throw ServiceError(fmt::format("{}: an exception that is not a std::exception", where));
    }
}

void Service::recordScalar(std::string_view name, double value) { emit(name, value); }

void Service::emit(std::string_view name, double value) {
    const Middleware& host = hostOf(middleware_);
    host.manager().statistics().record(host.vehicleId(), spec_ == nullptr ? std::string_view{} : spec_->type, name,
                                       simTime(), value);
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
