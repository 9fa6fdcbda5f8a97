#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/geonet/PacketHeader.h"

namespace sbsim::radio::geonet {

/// One station's duplicate packet detection (EN 302 636-4-1 Annex A.2): per source the last
/// kLength sequence numbers it handled. A source's packets come in sequence, so a short list per
/// source catches every duplicate that forwarding makes within the time a packet travels.
class SBSIM_API DuplicatePacketList {
public:
    static constexpr std::size_t kLength = 8;  ///< itsGnDPLLength

    /// Whether `id` was handled before; if not, it is remembered now (its source's oldest entry
    /// forgotten when the list is full).
    bool seen(const PacketId& id);
    bool contains(const PacketId& id) const;

private:
    struct Recent {
        std::array<std::uint16_t, kLength> sequence{};
        std::size_t size = 0, next = 0;  // entries used, where the next goes
    };
    std::unordered_map<std::string, Recent> bySource_;
};

}  // namespace sbsim::radio::geonet
