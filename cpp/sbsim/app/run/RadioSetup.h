#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/channel/ChannelSettings.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::app {

struct CommandLine;

/// The radio file (--radio, TOML): ChannelSettings' defaults overridden by the file's keys, then
/// by study parameters `radio_<key>` (`--param radio_power_dbm=30`), so a study sweeps them.
/// Throws InputError naming the file, key and problem; UsageError for a bad parameter.
radio::ChannelSettings readRadioSettings(const std::optional<std::filesystem::path>& file,
                                         const kernel::StudyParameters& parameters);

/// The run's medium, added to `sim`: the 802.11p channel model when --radio is given (its
/// buildings read from the loaded SUMO's polygons), else the disc model of the --v2x-* options.
radio::Medium& makeMedium(const CommandLine& cl, kernel::Simulation& sim, const traffic::VehicleSnapshot& snapshot,
                          radio::Medium::Directory directory);

}  // namespace sbsim::app
