#pragma once

#include "sbsim/app/cli/CommandLine.h"

namespace sbsim::app {

/// `--scenario X.xosc`: runs the OpenSCENARIO importer's first half (`python -m
/// storyboard.openscenario prepare`, before SUMO starts: the file read and checked, its network
/// found or converted, its entities' vehicle types written) and turns the run into a story run:
/// sets `options.story` to the generated story script, `options.sumocfg` (the given one, or the
/// one made for the scenario's OpenDRIVE network) and adds the vehicle types to SUMO's
/// additional files. An importer error is an InputError (its one line, exit 2).
void importOpenScenario(CommandLine& options);

}  // namespace sbsim::app
