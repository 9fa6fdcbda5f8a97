#pragma once

#include <cstddef>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/Color.h"

namespace sbsim::storyboard {

/// The colour a story is shown in (`sbsim --gui`: its vehicles and areas), by registration index:
/// matplotlib's ten "tab10" colours in their order, repeating, so that a story has the same colour
/// in sumo-gui as in `python -m sbsim.report`'s figures (C0, C1, ...).
SBSIM_API traffic::Color storyColour(std::size_t index);

}  // namespace sbsim::storyboard
