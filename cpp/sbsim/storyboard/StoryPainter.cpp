#include "sbsim/storyboard/StoryPainter.h"

#include "sbsim/storyboard/StoryPalette.h"
#include "sbsim/storyboard/effects/ColorEffect.h"

namespace sbsim::storyboard {

Effect* StoryPainter::onActivation(std::size_t storyIndex) {
    while (paints_.size() <= storyIndex) paints_.push_back(std::make_unique<ColorEffect>(storyColour(paints_.size())));
    return paints_[storyIndex].get();
}

}  // namespace sbsim::storyboard
