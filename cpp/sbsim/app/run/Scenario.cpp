#include "sbsim/app/run/Scenario.h"

#include <fmt/format.h>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/run/RadioSetup.h"
#include "sbsim/services/python/PythonServiceType.h"
#include "sbsim/storyboard/CanvasFrame.h"
#include "sbsim/traffic/EquippedView.h"
#include "sbsim/traffic/NetworkController.h"

namespace sbsim::app {

traffic::SumoSettings Scenario::sumoSettings(const CommandLine& options, const std::filesystem::path& sumocfg) {
    traffic::SumoSettings settings;
    settings.sumocfg = sumocfg;
    settings.extraOptions = options.sumoOptions;
    settings.seed = options.seed;
    if (options.end) settings.end = kernel::SimTime::fromSeconds(*options.end);
    settings.quiet = options.quiet;
    return settings;
}

Scenario::Scenario(const CommandLine& options, traffic::SumoSettings settings, unsigned threads)
    : options_(options),
      sumocfg_(settings.sumocfg),
      stations_(std::make_shared<facilities::StationRegistry>()),
      sim_(static_cast<std::uint64_t>(options.seed.value_or(CommandLine::kDefaultSeed)), threads),
      sumo_(sim_.emplaceModule<traffic::SumoBridge>(std::move(settings))),
      equipment_(
          std::make_unique<traffic::EquippedVehicles>(sumo_, traffic::Penetration(options.penetration, sim_.seed()))) {
    for (const std::string& param : options.params) {
        try {
            sim_.parameters().add(param);
        } catch (const kernel::StudyParameterError& e) {
            throw UsageError(fmt::format("--param: {}", e.what()));
        }
    }
    // The parameters that set options (CommandLine::complete applied them) count as read.
    for (const auto& [name, option] : CommandLine::optionParameters()) (void)sim_.parameters().get(name);
    vehicles_.attach(sumo_);
}

void Scenario::loadSumo() {
    try {
        sumo_.load();
    } catch (const traffic::SumoLoadError& e) {
        throw InputError(fmt::format("SUMO cannot load '{}': {}", sumocfg_.string(), e.what()));
    }
}

storyboard::StoryScript& Scenario::addStoryboard(const std::filesystem::path& story, storyboard::EventLog* log,
                                                 std::optional<traffic::Penetration> equippedOnly) {
    if (!python_) python_.emplace();
    board_ = &sim_.emplaceModule<storyboard::Storyboard>(vehicles_, log);
    board_->hearStations(stations_);
    board_->setStatistics(statistics_);
    board_->setPenetration(equipment_->penetration());
    // The vehicles a closure removes are told to the bridge, which reports them as arrived.
    board_->setNetworkController(std::make_unique<traffic::NetworkController>(&sumo_));
    std::optional<traffic::EquippedView> view;
    if (equippedOnly) view.emplace(*equippedOnly);
    feed_ = std::make_unique<storyboard::BoardFeed>(sumo_, sumo_.snapshot(), *board_, std::move(view));
    board_->onColumnsChanged([this](traffic::SnapshotColumns columns) { sumo_.demandColumns(columns); });
    script_ = std::make_unique<storyboard::StoryScript>(*python_, story, *board_,
                                                        storyboard::CanvasFrame(sumo_.netBoundary()));
    return *script_;
}

void Scenario::addServices(services::ServicesConfig config, kernel::SimTime interval,
                           const traffic::Penetration& penetration, radio::MessageTrace* trace) {
    // Python services are imported and checked as the manager is made: the interpreter first.
    if (services::python::usesPython(config) && !python_) python_.emplace();
    services_ = &sim_.emplaceModule<services::ServiceManager>(std::move(config), interval, sumo_.snapshot(), vehicles_);
    services_->setStatistics(statistics_);
    services::ServiceManager* manager = services_;
    medium_ = &makeMedium(
        options_, sim_, sumo_.snapshot(),
        [manager](const std::string& id) -> kernel::Module* { return manager->middlewareOf(id); }, &obstacles_);
    if (trace != nullptr) medium_->setTrace(trace);
    services_->useStations(stations_);
    services_->setMedium(*medium_);
    services_->setGeoNetworking(
        {.forwarding = options_.gnForwarding, .hopLimit = static_cast<std::uint8_t>(options_.gnHopLimit), .cbf = {}});
    services_->setPenetration(penetration);
    services_->attach(sumo_);
    sumo_.demandColumns(services::ServiceManager::columns());
}

void Scenario::requireStatisticsFile() {
    if (!python_) python_.emplace();
    try {
        parquet_.emplace();
    } catch (const python::StatisticsParquet::Unavailable& e) {
        throw UsageError(fmt::format("--statistics: {}", e.what()));
    }
}

std::unique_ptr<python::ParquetStream> Scenario::parquetStream(const std::string& option, int fd) {
    if (!python_) python_.emplace();
    try {
        return std::make_unique<python::ParquetStream>(fd);
    } catch (const python::ParquetStream::Unavailable& e) {
        throw UsageError(fmt::format("{}: {}", option, e.what()));
    }
}

std::string Scenario::statisticsFile() const {
    if (!parquet_) throw std::logic_error("requireStatisticsFile() was not called");
    return parquet_->bytes(statistics_, [this](std::string_view id) { return equipment_->isEquipped(id); });
}

std::vector<std::string> Scenario::abandonLingeringThreads() {
    if (!python_) return {};
    return python_->abandonLingeringThreads(python::PythonRuntime::kThreadGrace);
}

}  // namespace sbsim::app
