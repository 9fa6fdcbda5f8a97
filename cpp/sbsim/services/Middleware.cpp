#include "sbsim/services/Middleware.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sbsim/facilities/ItsMessage.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/CounterRandom.h"
#include "sbsim/services/IndicatedTypes.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/services/TriggerFree.h"

namespace sbsim::services {

Middleware::Middleware(ServiceManager& manager, std::string vehicleId)
    : kernel::Module(vehicleId + ".middleware"),
      manager_(manager),
      vehicleId_(std::move(vehicleId)),
      station_(manager.stations().intern(vehicleId_)),
      vehicle_(manager.registry().of(vehicleId_)),
      router_(vehicleId_, manager.geoNetworking()) {}

void Middleware::host(Service& service, const ServiceSpec& spec) {
    service.middleware_ = this;
    service.spec_ = &spec;
    service.setName(vehicleId_ + "." + spec.type);
    services_.push_back(&service);
    handlers_.push_back(dynamic_cast<facilities::ItsMessageHandler*>(&service));
    vehicles_.push_back(std::make_unique<ServiceVehicle>(vehicle_, manager_.registry()));
    const auto* declared = dynamic_cast<const IndicatedTypes*>(&service);
    taken_.push_back(declared ? std::optional(declared->indicatedTypes()) : std::nullopt);
    if (dynamic_cast<const TriggerFree*>(&service) == nullptr) triggered_ = true;
    if (manager_.hasMedium()) manager_.medium().setTypesTaken(vehicleId_, indicatedTypes());
}

std::optional<std::vector<std::string>> Middleware::indicatedTypes() const {
    std::vector<std::string> types;
    for (const auto& taken : taken_) {
        if (!taken) return std::nullopt;  // a service takes every type
        types.insert(types.end(), taken->begin(), taken->end());
    }
    return types;
}

bool Middleware::takes(std::size_t service, std::string_view type) const {
    const auto& taken = taken_[service];
    return !taken || std::find(taken->begin(), taken->end(), type) != taken->end();
}

ServiceVehicle& Middleware::vehicleOf(const Service& service) {
    for (std::size_t k = 0; k < services_.size(); ++k) {
        if (services_[k] == &service) return *vehicles_[k];
    }
    throw std::logic_error("the service is not hosted here");
}

std::optional<traffic::VehicleSnapshot::Index> Middleware::selfIndex() const {
    const auto& snapshot = manager_.snapshot();
    // Ids are unique: finding ours at the remembered index is finding our index.
    if (selfHint_ < snapshot.size() && snapshot.ids()[static_cast<std::size_t>(selfHint_)] == vehicleId_)
        return selfHint_;
    const auto index = snapshot.indexOf(vehicleId_);
    if (index) selfHint_ = *index;
    return index;
}

Eigen::Vector2d Middleware::position() const {
    if (fixedPosition_) return *fixedPosition_;
    const auto index = selfIndex();
    if (!index) return Eigen::Vector2d::Zero();
    return manager_.snapshot().positions().col(*index);
}

kernel::SimTime Middleware::clockPhase(std::uint64_t seed, std::string_view station, kernel::SimTime interval) {
    radio::CounterRandom random(seed, radio::CounterRandom::keyOf(station), 0, 0, radio::DrawPurpose::ClockPhase);
    // 1 - u lies in (0, 1]: a station never triggers in the instant it departs (its services have
    // just been initialized, and the step's snapshot may not hold it yet).
    const double phase = (1.0 - random.uniform01()) * static_cast<double>(interval.raw());
    return kernel::SimTime::fromNanoseconds(
        std::clamp(static_cast<kernel::SimTime::rep>(std::ceil(phase)), kernel::SimTime::rep{1}, interval.raw()));
}

void Middleware::initialize() {
    (void)manager_.stations().of(station_);  // the station's facilities, empty, from its departure on
    // The first trigger is scheduled whatever the services (they are hosted after this); a station
    // whose services turn out TriggerFree stops its clock there if it heard nothing.
    firstTrigger_ = simTime() + clockPhase(simulation().seed(), vehicleId_, manager_.interval());
    scheduleAt(firstTrigger_, triggerTimer_);
}

facilities::StationFacilities& Middleware::facilities() const { return manager_.stations().of(station_); }

void Middleware::trigger() {
    manager_.stations().dropExpired(station_, simTime());
    for (Service* s : services_) {
        try {
            s->trigger();
        } catch (...) {
            s->failed();
        }
    }
}

const facilities::ItsMessage* Middleware::itsPart(const radio::V2xMessage& message) {
    const std::type_info* type = &typeid(message);
    // ItsMessage derives from V2xMessage alone and not virtually: once a type is known to be
    // one, the static downcast is the dynamic one's result.
    if (type == itsType_) return static_cast<const facilities::ItsMessage*>(&message);
    if (type == otherType_) return nullptr;
    const auto* its = dynamic_cast<const facilities::ItsMessage*>(&message);
    (its != nullptr ? itsType_ : otherType_) = type;
    return its;
}

std::vector<radio::geonet::Neighbour> Middleware::neighbours() const {
    std::vector<radio::geonet::Neighbour> out;
    const kernel::SimTime now = simTime();
    for (const auto& [station, entry] : facilities().ldm.entries()) {
        if (entry.expiry() >= now) out.push_back({station, entry.cam.position});
    }
    // In ascending id order, whatever the LDM's: greedy forwarding takes the first of equals.
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.station < b.station; });
    return out;
}

void Middleware::send(std::unique_ptr<radio::V2xMessage> message) {
    if (!message) throw std::invalid_argument("cannot send a null V2X message");
    if (message->geonet().geoBroadcast()) router_.originate(*message, position(), [this] { return neighbours(); });
    broadcast(std::move(message));
}

void Middleware::broadcast(std::unique_ptr<radio::V2xMessage> message) {
    radio::Medium& medium = manager_.medium();
    if (!radioIndex_) radioIndex_ = medium.stationIndex(vehicleId_);
    medium.broadcastFrom(*radioIndex_, vehicleId_, std::move(message));
}

void Middleware::wake() {
    if (facilities().empty()) return;  // nothing was kept (a CAM or DENM already past its time)
    const kernel::SimTime now = simTime();
    const kernel::SimTime interval = manager_.interval();
    kernel::SimTime next = firstTrigger_;
    if (next <= now) next += interval * ((now - firstTrigger_).raw() / interval.raw() + 1);
    scheduleAt(next, triggerTimer_);
}

void Middleware::scheduleForwarding() {
    const std::optional<kernel::SimTime> due = router_.nextTimeout();
    if (forwardTimer_.isScheduled() && (!due || forwardTimer_.arrivalTime() != *due)) cancelEvent(forwardTimer_);
    if (due && !forwardTimer_.isScheduled()) scheduleAt(*due, forwardTimer_);
}

void Middleware::handleMessage(kernel::Message& msg) {
    if (&msg == &triggerTimer_) {
        // Scheduled before the services run, as always: the next trigger's place among the events of
        // one instant does not change.
        scheduleAfter(manager_.interval(), triggerTimer_);
        trigger();
        // Nothing can expire before something is stored (wake()); the services do nothing on a trigger.
        if (!triggered_ && triggerTimer_.isScheduled() && facilities().empty()) cancelEvent(triggerTimer_);
        return;
    }
    if (&msg != &forwardTimer_) return kernel::Module::handleMessage(msg);
    for (auto& packet : router_.takeExpired(simTime(), position())) broadcast(std::move(packet));
    scheduleForwarding();
}

void Middleware::receive(const radio::V2xMessage& message) {
    if (message.geonet().geoBroadcast()) {
        radio::geonet::Router::Reception r =
            router_.receive(message, position(), simTime(), [this] { return neighbours(); });
        if (r.forwardNow) broadcast(std::move(r.forwardNow));
        if (r.timersChanged) scheduleForwarding();
        if (!r.passUp) return;
    }
    // A cast to the facilities' interface, not a switch on concrete types: the message itself
    // says where it goes and what is kept of it.
    const facilities::ItsMessage* its = itsPart(message);
    if (its != nullptr) {
        if (!its->reaches(position())) return;
        its->store(manager_.stations(), station_, simTime());
        if (!triggerTimer_.isScheduled()) wake();
    }
    for (std::size_t k = 0; k < services_.size(); ++k) {
        if (!takes(k, message.typeName())) continue;
        try {
            services_[k]->indicate(message);
        } catch (...) {
            services_[k]->failed();
        }
    }
    if (its != nullptr) {
        for (std::size_t k = 0; k < services_.size(); ++k) {
            if (handlers_[k] == nullptr) continue;
            try {
                its->dispatch(*handlers_[k]);
            } catch (...) {
                services_[k]->failed();
            }
        }
    }
}

void Middleware::signal(const traffic::StoryboardSignal& signal) {
    for (Service* s : services_) {
        try {
            s->receiveSignal(signal);
        } catch (...) {
            s->failed();
        }
    }
}

}  // namespace sbsim::services
