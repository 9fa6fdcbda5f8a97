#include "sbsim/services/ServiceManager.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

#include "sbsim/facilities/ItsMessage.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/services/NeedsVehicle.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::services {

ServiceManager::ServiceManager(ServicesConfig config, kernel::SimTime interval,
                               const traffic::VehicleSnapshot& snapshot, traffic::VehicleRegistry& registry)
    : kernel::Module("services"),
      config_(std::move(config)),
      interval_(interval),
      snapshot_(snapshot),
      registry_(&registry) {
    if (interval_ <= kernel::SimTime::zero()) throw std::invalid_argument("the middleware interval must be > 0 s");
    // Fail before the run, naming the line, rather than at the first matching departure.
    const auto check = [](const ServiceSpec& spec) { ServiceRegistry::instance().check(spec); };
    for (const ServiceSpec& spec : config_.services()) check(spec);
    for (const RoadsideUnitSpec& rsu : config_.roadsideUnits()) {
        for (const ServiceSpec& spec : rsu.services) check(spec);
    }
}

ServiceManager::~ServiceManager() = default;

void ServiceManager::initialize() {
    simulation().subscribe(traffic::StoryboardSignal::id, *this);
    makeRoadsideUnits();
}

void ServiceManager::makeRoadsideUnits() {
    const auto where = [](const RoadsideUnitSpec& spec) {
        return spec.source + ":" + std::to_string(spec.line) + ": ";
    };
    std::optional<std::vector<traffic::SumoPois::Poi>> pois;  // asked for once, if a unit names a type
    for (const RoadsideUnitSpec& spec : config_.roadsideUnits()) {
        if (!spec.poiType) {
            makeRoadsideUnit(spec, spec.id, {spec.x, spec.y});
            continue;
        }
        if (!pois) pois = pois_();
        std::size_t made = 0;
        std::vector<std::string> types;
        for (const traffic::SumoPois::Poi& poi : *pois) {
            if (poi.type == *spec.poiType) {
                makeRoadsideUnit(spec, poi.id, poi.position);
                ++made;
            } else if (std::find(types.begin(), types.end(), poi.type) == types.end()) {
                types.push_back(poi.type);
            }
        }
        if (made == 0) {
            throw ServicesConfigError(
                where(spec) + fmt::format("<rsu poiType=\"{}\">: SUMO has no POI of that type ({})", *spec.poiType,
                                          types.empty()
                                              ? std::string("it loaded no POIs: they come from <poi> "
                                                            "elements in the sumocfg's additional-files")
                                              : "its POI types: " + fmt::format("{}", fmt::join(types, ", "))));
        }
    }
}

void ServiceManager::makeRoadsideUnit(const RoadsideUnitSpec& spec, const std::string& id,
                                      const Eigen::Vector2d& position) {
    if (!roadsideUnitIds_.emplace(id, &spec).second) {
        throw ServicesConfigError(spec.source + ":" + std::to_string(spec.line) + ": two roadside units are called '" +
                                  id + "'");
    }
    auto& middleware = simulation().emplaceModule<Middleware>(*this, id);
    middleware.setFixedPosition(position);
    roadsideUnits_.push_back(&middleware);
    middlewares_[id] = &middleware;  // the medium finds a station's receiving side here
    if (medium_ != nullptr) {
        medium_->stationChanged(id);
        medium_->addFixedStation(id, position);
    }
    for (const ServiceSpec& serviceSpec : spec.services) {
        std::unique_ptr<Service> service = ServiceRegistry::instance().create(serviceSpec);
        const auto* vehicleOnly = dynamic_cast<const NeedsVehicle*>(service.get());
        if (const std::string_view why = vehicleOnly ? vehicleOnly->whyVehicle() : ""; !why.empty()) {
            throw ServicesConfigError(fmt::format("{}:{}: {} cannot run on roadside unit '{}': {}", serviceSpec.source,
                                                  serviceSpec.line, serviceSpec.type, id, why));
        }
        middleware.host(*service, serviceSpec);
        simulation().addModule(std::move(service));
        ++servicesCreated_;
    }
}

void ServiceManager::listenToAllSignals(Service& service) {
    if (std::find(allSignals_.begin(), allSignals_.end(), &service) == allSignals_.end())
        allSignals_.push_back(&service);
}

void ServiceManager::attach(kernel::Module& sumo) {
    sumo.subscribe(traffic::SumoBridge::departedSignal, *this);
    sumo.subscribe(traffic::SumoBridge::arrivedSignal, *this);
}

void ServiceManager::setMedium(radio::Medium& medium) {
    medium_ = &medium;
    // The medium's directory is middlewareOf(): every change of its answers is reported (stationChanged).
    medium.reportStationChanges();
    medium.setLayersTake([](const radio::V2xMessage& message) {
        return dynamic_cast<const facilities::ItsMessage*>(&message) != nullptr;
    });
}

radio::Medium& ServiceManager::medium() const {
    if (medium_ == nullptr) throw std::logic_error("no V2X medium in this simulation");
    return *medium_;
}

kernel::Statistics& ServiceManager::statistics() const {
    if (statistics_ == nullptr) throw std::logic_error("no statistics recorder in this simulation");
    return *statistics_;
}

Middleware* ServiceManager::middlewareOf(const std::string& vehicleId) const {
    const auto it = middlewares_.find(vehicleId);
    return it == middlewares_.end() ? nullptr : it->second;
}

void ServiceManager::receiveSignal(kernel::Module&, kernel::SignalId id, std::string_view value) {
    if (id == traffic::SumoBridge::departedSignal) {
        depart(std::string(value));
    } else if (id == traffic::SumoBridge::arrivedSignal) {
        arrive(std::string(value));
    }
}

void ServiceManager::receiveSignal(kernel::Module&, kernel::SignalId id, const kernel::Object& value) {
    if (id != traffic::StoryboardSignal::id) return;
    const auto& signal = dynamic_cast<const traffic::StoryboardSignal&>(value);
    Middleware* ego = middlewareOf(signal.ego);
    if (ego != nullptr) {
        ego->signal(signal);
    } else if (signalsWithoutServices_++ == 0) {
        // Likely a filter in the services file that leaves the story's vehicles out.
        fmt::print(stderr,
                   "sbsim: warning: t={} s: story '{}' signalled '{}' to vehicle {}, which has no services; further "
                   "such signals are only counted (summary: signals without services)\n",
                   simTime().str(), signal.story, signal.cause, signal.ego);
    }
    // Index loop over the listeners present now: a listener may start listening to all meanwhile.
    const std::size_t listeners = allSignals_.size();
    for (std::size_t i = 0; i < listeners && i < allSignals_.size(); ++i) {
        Service* s = allSignals_[i];
        if (ego != nullptr && s->vehicleId() == signal.ego) continue;
        try {
            s->receiveSignal(signal);
        } catch (...) {
            s->failed();
        }
    }
}

void ServiceManager::depart(const std::string& id) {
    if (const auto rsu = roadsideUnitIds_.find(id); rsu != roadsideUnitIds_.end()) {
        // One station id, two stations: the medium and the facilities could not tell them apart.
        throw ServicesConfigError(fmt::format("{}:{}: roadside unit '{}' has the id of a vehicle departing at t={} s",
                                              rsu->second->source, rsu->second->line, id, simTime().str()));
    }
    const auto index = snapshot_.indexOf(id);
    const std::string type = index ? snapshot_.typeId(*index) : std::string();
    const bool equipped = penetration_.equipped(id);
    std::vector<const ServiceSpec*> selected;
    for (const ServiceSpec& spec : config_.services()) {
        if (spec.admits(equipped) && spec.matches(id, type)) selected.push_back(&spec);
    }
    if (selected.empty()) return;
    auto& middleware = simulation().emplaceModule<Middleware>(*this, id);
    middlewares_[id] = &middleware;
    if (medium_ != nullptr) medium_->stationChanged(id);
    for (const ServiceSpec* spec : selected) {
        std::unique_ptr<Service> service = ServiceRegistry::instance().create(*spec);
        // Hosted before it joins the simulation: initialize() may already use vehicle() or send().
        middleware.host(*service, *spec);
        simulation().addModule(std::move(service));
        ++servicesCreated_;
    }
}

void ServiceManager::arrive(const std::string& id) {
    const auto it = middlewares_.find(id);
    if (it == middlewares_.end()) return;
    Middleware& middleware = *it->second;
    middlewares_.erase(it);
    if (medium_ != nullptr) medium_->stationChanged(id);  // before its services' finish() may send
    for (Service* s : middleware.services()) {
        std::erase(allSignals_, s);
        simulation().removeModule(*s);  // finish(), then its timers are dropped
    }
    simulation().removeModule(middleware);
    stations_->remove(id);
    registry_->drop(id);
}

}  // namespace sbsim::services
