#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/propagation/Obstacles.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::app {

struct CommandLine;

/// What the channel model took as buildings: the summary and `sbsim check` report it.
struct ObstacleFigures {
    std::string polygonType;
    std::size_t count = 0;
    std::shared_ptr<const radio::Obstacles> model;  // its links evaluated, read at the run's end
};

/// The run's medium, added to `sim`: the 802.11p channel model when --radio is given (the file
/// read by radio::readRadioFile, study parameters `radio_<key>` over it; its buildings read from the
/// loaded SUMO's polygons, their figures put in `obstacles` if given), else the disc model of the
/// --v2x-* options. A polygon type matching none of the scenario's polygons (when it has some) is
/// an InputError naming the types it has: a misspelt type would silently take every building away.
radio::Medium& makeMedium(const CommandLine& cl, kernel::Simulation& sim, const traffic::VehicleSnapshot& snapshot,
                          radio::Medium::Directory directory, std::optional<ObstacleFigures>* obstacles = nullptr);

}  // namespace sbsim::app
