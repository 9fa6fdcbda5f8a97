#pragma once

#include <cstddef>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Watches stories activate for vehicles and may dress the activation with an effect of its own
/// (sbsim --gui paints a vehicle in its story's colour): the board applies that effect before
/// the story's effects and removes it after them. The program owns the observer.
class SBSIM_API ActivationObserver {
public:
    virtual ~ActivationObserver() = default;
    /// The story registered `storyIndex`-th activates for a vehicle: an effect to apply first, or
    /// none. The effect must live as long as the board.
    virtual Effect* onActivation(std::size_t storyIndex) = 0;
};

}  // namespace sbsim::storyboard
