#pragma once

#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::app {

struct CommandLine;

/// The run's medium, added to `sim`: the 802.11p channel model when --radio is given (the file
/// read by radio::readRadioFile, study parameters `radio_<key>` over it; its buildings from the
/// loaded SUMO's polygons), else the disc model of the --v2x-* options.
radio::Medium& makeMedium(const CommandLine& cl, kernel::Simulation& sim, const traffic::VehicleSnapshot& snapshot,
                          radio::Medium::Directory directory);

}  // namespace sbsim::app
