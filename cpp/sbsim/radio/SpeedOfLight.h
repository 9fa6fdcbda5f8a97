#pragma once

namespace sbsim::radio {

/// m/s, exact by the SI definition.
inline constexpr double kSpeedOfLight = 299'792'458.0;

}  // namespace sbsim::radio
