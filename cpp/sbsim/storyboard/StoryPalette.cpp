#include "sbsim/storyboard/StoryPalette.h"

#include <array>

namespace sbsim::storyboard {

traffic::Color storyColour(std::size_t index) {
    static constexpr std::array<traffic::Color, 10> kTab10{{
        {31, 119, 180, 255},   // blue
        {255, 127, 14, 255},   // orange
        {44, 160, 44, 255},    // green
        {214, 39, 40, 255},    // red
        {148, 103, 189, 255},  // purple
        {140, 86, 75, 255},    // brown
        {227, 119, 194, 255},  // pink
        {127, 127, 127, 255},  // grey
        {188, 189, 34, 255},   // olive
        {23, 190, 207, 255},   // cyan
    }};
    return kTab10[index % kTab10.size()];
}

}  // namespace sbsim::storyboard
