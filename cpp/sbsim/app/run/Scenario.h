#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/app/cli/CommandLine.h"
#include "sbsim/app/run/RadioSetup.h"
#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/kernel/Statistics.h"
#include "sbsim/python/ParquetStream.h"
#include "sbsim/python/PythonRuntime.h"
#include "sbsim/python/StatisticsParquet.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/MessageTrace.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/storyboard/BoardFeed.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/python/StoryScript.h"
#include "sbsim/traffic/EquippedVehicles.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/SumoBridge.h"
#include "sbsim/traffic/VehicleRegistry.h"

namespace sbsim::app {

/// One scenario assembled as the command line says, the one way `sbsim run` and `sbsim check`
/// both build it: the simulation (seeded, its threads, the --param study parameters), the SUMO
/// bridge, the vehicle registry that the stories and the services both command through, and on
/// demand the storyboard with its script and the services with their medium. Parts are added in
/// that order; each is wired to the bridge as it is added.
class Scenario {
public:
    /// What the command line says SUMO is to run: the sumocfg, SUMO's words, --seed, --end, --quiet.
    static traffic::SumoSettings sumoSettings(const CommandLine& options, const std::filesystem::path& sumocfg);

    /// Makes the simulation, the (not yet loaded) SUMO bridge and the record of which vehicles are
    /// equipped (--penetration). Throws UsageError for a bad --param.
    Scenario(const CommandLine& options, traffic::SumoSettings settings, unsigned threads);
    Scenario(const Scenario&) = delete;
    Scenario& operator=(const Scenario&) = delete;

    /// Loads SUMO; throws InputError naming the sumocfg when SUMO cannot.
    void loadSumo();
    /// Adds the storyboard (events to `log`, if given; its conditions and criteria know who is
    /// equipped; with `equippedOnly`, the stories see only those vehicles) and loads the story script, whose
    /// createStories() is still to run.
    storyboard::StoryScript& addStoryboard(const std::filesystem::path& story, storyboard::EventLog* log,
                                           std::optional<traffic::Penetration> equippedOnly = std::nullopt);
    /// Starts the interpreter (if no story did) and makes sure the statistics file can be written
    /// (pyarrow); throws UsageError naming --statistics if not.
    void requireStatisticsFile();
    /// The run's statistics as the --statistics file's bytes (after requireStatisticsFile()).
    std::string statisticsFile() const;
    /// Starts the interpreter (if no story did) and pyarrow's writer for a Parquet file written
    /// as the run goes to `fd`; throws UsageError naming `option` if pyarrow is missing.
    std::unique_ptr<python::ParquetStream> parquetStream(const std::string& option, int fd);

    /// Adds the services with the medium the command line chooses (--radio: the 802.11p channel
    /// model, else the disc model of the --v2x-* options), its lines going to `trace` if given.
    void addServices(services::ServicesConfig config, kernel::SimTime interval, const traffic::Penetration& penetration,
                     radio::MessageTrace* trace);

    kernel::Simulation& simulation() { return sim_; }
    traffic::SumoBridge& sumo() { return sumo_; }
    /// Null until added.
    storyboard::Storyboard* board() { return board_; }
    services::ServiceManager* services() { return services_; }
    radio::Medium* medium() { return medium_; }
    /// The channel model's buildings (--radio); none for the disc model or before addServices().
    const std::optional<ObstacleFigures>& obstacles() const { return obstacles_; }
    /// What every station heard (LDMs, DENM memories): written by the services, read by the
    /// stories' V2X conditions.
    facilities::StationRegistry& stations() { return *stations_; }
    /// Which vehicles departed V2X-equipped, and when (the services' penetration draw).
    traffic::EquippedVehicles& equipment() { return *equipment_; }
    const traffic::EquippedVehicles& equipment() const { return *equipment_; }
    /// What the services and the stories recorded (recordScalar, emit, board.record).
    const kernel::Statistics& statistics() const { return statistics_; }
    /// Threads the story script left running, abandoned after a grace period (their names).
    std::vector<std::string> abandonLingeringThreads();

private:
    const CommandLine& options_;
    std::filesystem::path sumocfg_;
    // Destroyed bottom up: the script's Python objects before the board, the simulation before
    // the registry its modules hold entries of, the interpreter last.
    std::optional<python::PythonRuntime> python_;  // outlives the stories' Python objects
    traffic::VehicleRegistry vehicles_;            // outlives the simulation, whose modules hold its entries
    std::shared_ptr<facilities::StationRegistry> stations_;
    kernel::Statistics statistics_;  // outlives the simulation: services record in finish()
    std::optional<python::StatisticsParquet> parquet_;
    kernel::Simulation sim_;
    traffic::SumoBridge& sumo_;
    std::unique_ptr<traffic::EquippedVehicles> equipment_;
    storyboard::Storyboard* board_ = nullptr;
    std::unique_ptr<storyboard::StoryScript> script_;
    std::unique_ptr<storyboard::BoardFeed> feed_;
    services::ServiceManager* services_ = nullptr;
    radio::Medium* medium_ = nullptr;
    std::optional<ObstacleFigures> obstacles_;
};

}  // namespace sbsim::app
