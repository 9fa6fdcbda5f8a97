#include "sbsim/services/den/DenService.h"

#include <algorithm>

#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/services/den/UseCaseFactory.h"

namespace sbsim::services {

SBSIM_REGISTER_SERVICE(DenService);

namespace {
/// A repetition timer names its event.
struct RepetitionTimer : kernel::Message {
    explicit RepetitionTimer(facilities::ActionId a) : kernel::Message("denm repetition"), action(std::move(a)) {}
    facilities::ActionId action;
};
}  // namespace

DenService::DenService() = default;

DenService::~DenService() {
    for (auto& [action, active] : active_) {
        if (active.timer) cancelEvent(*active.timer);
    }
}

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

facilities::ActionId DenService::requestActionId() { return {stationId(), ++sequence_}; }

void DenService::transmit(const facilities::DenmContent& denm) {
    send(std::make_unique<facilities::Denm>(denm));
    ++sent_;
}

void DenService::sendDenm(const facilities::DenmContent& denm, std::optional<Repetition> repetition) {
    const bool update = sentEvents_.count(denm.action) != 0;
    sentEvents_[denm.action] = denm;
    transmit(denm);
    stations().report({simTime(), update ? facilities::DenmPhase::Update : facilities::DenmPhase::New, stationId(),
                       denm.action, denm.cause});
    if (!repetition || repetition->interval <= kernel::SimTime::zero() ||
        repetition->interval >= repetition->duration) {
        return;
    }
    Active& active = active_[denm.action];
    if (active.timer) cancelEvent(*active.timer);
    active.denm = denm;
    active.repetition = *repetition;
    active.first = simTime();
    active.timer = std::make_unique<RepetitionTimer>(denm.action);
    scheduleAfter(repetition->interval, *active.timer);
}

void DenService::handleMessage(kernel::Message& msg) {
    auto* timer = dynamic_cast<RepetitionTimer*>(&msg);
    if (timer == nullptr) return Service::handleMessage(msg);
    const auto it = active_.find(timer->action);
    if (it == active_.end()) return;
    Active& active = it->second;
    transmit(active.denm);
    const kernel::SimTime next = simTime() + active.repetition.interval;
    if (next - active.first < active.repetition.duration) {
        scheduleAt(next, *active.timer);
    } else {
        active_.erase(it);  // the timer is not scheduled: it may go
    }
}

void DenService::terminate(const facilities::ActionId& action) {
    const auto last = sentEvents_.find(action);
    if (last == sentEvents_.end()) return;
    facilities::DenmContent cancel = last->second;
    sentEvents_.erase(last);
    const auto it = active_.find(action);
    if (it != active_.end()) {
        if (it->second.timer) cancelEvent(*it->second.timer);
        active_.erase(it);
    }
    cancel.referenceTime = simTime();
    cancel.termination = facilities::Termination::Cancellation;
    transmit(cancel);
    stations().report({simTime(), facilities::DenmPhase::Terminate, stationId(), action, cancel.cause});
}

}  // namespace sbsim::services
