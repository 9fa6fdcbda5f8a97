#pragma once

#include <compare>
#include <cstdint>
#include <string>

#include "sbsim/kernel/Export.h"

namespace sbsim::facilities {

/// A DENM event's identity (EN 302 637-3 ActionID): the originating station and its sequence number.
struct SBSIM_API ActionId {
    std::string station;
    std::uint32_t sequence = 0;

    auto operator<=>(const ActionId&) const = default;
    /// "<station>:<sequence>", as the traces show it.
    std::string str() const;
};

}  // namespace sbsim::facilities
