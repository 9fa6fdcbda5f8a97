#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio {

/// The run's station ids (SUMO vehicle ids, roadside unit names) interned as dense indices 0, 1,
/// 2, … in the order they were first asked for. A name keeps its index for the whole run, even
/// after its station left, and an index is never given to another name: so tables keyed by index
/// (a station's facilities, the senders its LDM knows) need one string lookup per station, not one
/// per message, and stay deterministic whatever the thread count.
class SBSIM_API StationIds {
public:
    using Index = std::uint32_t;

    /// The index of `name`, made on its first use.
    Index intern(std::string_view name);
    /// The index of `name`, if it was interned.
    std::optional<Index> find(std::string_view name) const;
    const std::string& name(Index index) const { return *names_[index]; }
    std::size_t size() const { return names_.size(); }

private:
    struct Hash {
        using is_transparent = void;
        std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
    };
    std::unordered_map<std::string, Index, Hash, std::equal_to<>> indices_;
    std::vector<const std::string*> names_;  // the keys of indices_ (nodes do not move), by index
};

}  // namespace sbsim::radio
