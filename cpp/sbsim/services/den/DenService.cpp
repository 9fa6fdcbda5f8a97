#include "sbsim/services/den/DenService.h"

#include <algorithm>

#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/services/den/UseCaseFactory.h"

namespace sbsim::services {

SBSIM_REGISTER_SERVICE(DenService);

DenService::DenService() = default;

DenService::~DenService() = default;

void DenService::initialize() {
    const ServiceSpec& spec = this->spec();
    const auto index = selfIndex();
    const std::string type = index ? snapshot().typeId(*index) : std::string();
    const auto add = [&](const ServiceSpec& useCase) {
        auto made = makeUseCase(useCase.type);
        made->attach(*this, useCase);
        made->initialize();
        useCases_.push_back(std::move(made));
    };
    if (spec.useCases != nullptr) {
        for (const ServiceSpec& useCase : *spec.useCases) {
            if (useCase.matches(vehicleId(), type)) add(useCase);
        }
    } else {
        // No use-case list: all of them, with their defaults (Artery's DenService.ned default).
        for (const std::string& name : useCaseNames()) {
            ServiceSpec s;
            s.type = name;
            s.source = spec.source;
            s.line = spec.line;
            allUseCases_.push_back(std::move(s));
        }
        for (const ServiceSpec& s : allUseCases_) add(s);
    }
}

double DenService::stationSpeed() const {
    const auto index = selfIndex();
    return index ? snapshot().speeds()[*index] : 0.0;
}

double DenService::stationAcceleration() const {
    const auto index = selfIndex();
    return index ? snapshot().accelerations()[*index] : 0.0;
}

double DenService::stationHeading() const {
    const auto index = selfIndex();
    return index ? snapshot().angles()[*index] : 0.0;
}

void DenService::trigger() {
    for (auto& useCase : useCases_) useCase->check();
}

void DenService::receiveSignal(const traffic::StoryboardSignal& signal) {
    if (signal.ego != vehicleId()) return;
    for (auto& useCase : useCases_) useCase->handleSignal(signal);
}

void DenService::indicateDenm(const facilities::Denm& denm) {
    for (auto& useCase : useCases_) useCase->indicate(denm);
}

void DenService::handleMessage(kernel::Message& msg) {
    if (!sender_.handle(msg)) Service::handleMessage(msg);
}

}  // namespace sbsim::services
