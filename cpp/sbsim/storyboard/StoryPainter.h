#pragma once

#include <memory>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/ActivationObserver.h"

namespace sbsim::storyboard {

/// Shows which story acts on a vehicle (`sbsim --gui`): while a story is active on a vehicle, the
/// vehicle takes the story's colour (storyColour of its registration index). The colour goes on
/// the vehicle's effect stack before the story's own effects, as one more colour effect, so a
/// ColorEffect of the story wins over it, the latest activated story's colour wins among stories,
/// and the vehicle's own colour comes back when none is active.
class SBSIM_API StoryPainter : public ActivationObserver {
public:
    Effect* onActivation(std::size_t storyIndex) override;

private:
    std::vector<std::unique_ptr<Effect>> paints_;  // per story, made on its first activation
};

}  // namespace sbsim::storyboard
