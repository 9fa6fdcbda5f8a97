#pragma once

#include <cstdint>

namespace sbsim::traffic {

/// A vehicle's colour as SUMO keeps it: 8-bit red, green, blue and alpha.
struct Color {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    std::uint8_t a = 255;
    bool operator==(const Color&) const = default;
};

}  // namespace sbsim::traffic
