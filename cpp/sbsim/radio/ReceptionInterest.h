#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/StationIds.h"

namespace sbsim::radio {

/// Which message types each station's receiving side takes, by station index, as Artery's
/// services listen on BTP ports: a station restricted to some types is not handed the others.
/// Kept as bit sets so that a frame's receivers are filtered by one bit test each, in the
/// medium's tables, without reaching the stations themselves (a cache miss per reception).
class SBSIM_API ReceptionInterest {
public:
    using Index = StationIds::Index;

    /// From now on `station` takes only `types` (none: every type, the default).
    void set(Index station, const std::optional<std::vector<std::string>>& types);
    /// Whether some station is restricted; if none, every receiver takes everything.
    bool anyRestricted() const { return restricted_ > 0; }
    /// Whether set() was called for `station`.
    bool registered(Index station) const { return Takers::test(&registeredBits_, station); }

    /// Who takes a frame of one type.
    class Takers {
    public:
        bool takes(Index station) const { return !test(restricted_, station) || test(typed_, station); }
        /// Whether no registered station takes the type: none takes every type, no restricted one takes it.
        bool noRegisteredTaker() const { return noRegisteredTaker_; }

    private:
        friend class ReceptionInterest;
        static bool test(const std::vector<std::uint64_t>* bits, Index station) {
            const std::size_t word = station / 64;
            return bits != nullptr && word < bits->size() && ((*bits)[word] >> (station % 64) & 1U) != 0;
        }
        const std::vector<std::uint64_t>* restricted_ = nullptr;
        const std::vector<std::uint64_t>* typed_ = nullptr;  // the restricted stations taking the type
        bool noRegisteredTaker_ = false;
    };
    Takers takersOf(std::string_view type) const;

private:
    /// Sets `station`'s bit; whether it changed.
    static bool assign(std::vector<std::uint64_t>& bits, Index station, bool value);

    std::vector<std::uint64_t> restrictedBits_, registeredBits_;
    std::size_t restricted_ = 0;
    std::size_t unrestricted_ = 0;  // registered, taking every type
    struct Typed {
        std::vector<std::uint64_t> bits;  // the restricted stations taking it
        std::size_t count = 0;
    };
    std::map<std::string, Typed, std::less<>> typed_;
    std::vector<std::vector<std::string>> typesOf_;  // by station, while restricted
};

}  // namespace sbsim::radio
