#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/Ziggurat.h"

namespace sbsim::radio {

/// What a radio draw is for: part of its key, so two purposes on the same link never share a number.
enum class DrawPurpose : std::uint64_t {
    Shadowing = 1,
    Fading = 2,
    Decode = 3,
    Backoff = 4,
    Start = 5,
    Delay = 6,
    // 7 is the middleware clock phase on main (issue 27 part 2): the next number, so both merge.
    CorrelatedShadowing = 8,  // keyed by (seed, pair, update) instead of a frame
};

/// A counter-based random generator: every number is a pure function of its key (seed, sender,
/// sequence number, receiver, purpose) and a counter, like Philox or Random123's generators. No
/// state is shared between draws, so the radio's results do not depend on which thread computes
/// a link or in which order links are evaluated.
class SBSIM_API CounterRandom {
public:
    /// The stream of one draw's key. `receiver` is 0 for draws of the sender alone (backoff).
    CounterRandom(std::uint64_t seed, std::uint64_t sender, std::uint64_t sequence, std::uint64_t receiver,
                  DrawPurpose purpose);
    /// The part of a key that every link of one frame shares: (seed, sender, sequence) mixed once,
    /// so a frame's hundreds of links each mix only their receiver and purpose.
    static std::uint64_t frameKey(std::uint64_t seed, std::uint64_t sender, std::uint64_t sequence);
    /// The same stream as CounterRandom(seed, sender, sequence, receiver, purpose), from
    /// frameKey(seed, sender, sequence).
    static CounterRandom ofFrame(std::uint64_t frameKey, std::uint64_t receiver, DrawPurpose purpose) {
        return {Keyed{}, frameKey, receiver, purpose};
    }

    /// A stable 64-bit key for a station id (FNV-1a then mixed), the same on every platform.
    static std::uint64_t keyOf(std::string_view stationId);
    /// SplitMix64's finalizer: a bijection of 64-bit words with good avalanche.
    static constexpr std::uint64_t mix(std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }

    /// The next 64 random bits of this stream (counter 0, 1, 2, …).
    std::uint64_t next() {
        // Two rounds: the first decorrelates consecutive counters of one key, the second the keys.
        return mix(mix(key_ + (counter_++) * 0x9E3779B97F4A7C15ULL) ^ key_);
    }
    /// Uniform in [0, 1), 53 bits.
    double uniform01() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Standard normal by Marsaglia and Tsang's ziggurat (Ziggurat.h); inline for the ~99 % of draws
    /// one word decides.
    double normal() {
        const Ziggurat& z = Ziggurat::instance();
        const std::uint64_t bits = next();  // layer from bits 0–7, sign from bit 8, position from 11–63
        const auto layer = static_cast<std::size_t>(bits & 0xFF);
        const double t = static_cast<double>(bits >> 11) * 0x1.0p-53 * z.x[layer];
        if (t < z.x[layer + 1]) return (bits & 0x100) != 0 ? -t : t;
        return normalBeyondBoxes(bits);
    }
    /// Gamma(shape k, scale 1) by Marsaglia and Tsang's method (k > 0).
    double gamma(double shape);

private:
    struct Keyed {};
    CounterRandom(Keyed, std::uint64_t frameKey, std::uint64_t receiver, DrawPurpose purpose)
        : key_(mix(mix(frameKey ^ (receiver + 0x8CB92BA72F3D8DD7ULL)) ^
                   (static_cast<std::uint64_t>(purpose) + 0xF1357AEA2E62A9C5ULL))) {}
    /// The wedge and tail cases of normal(), from the first word `bits` on.
    double normalBeyondBoxes(std::uint64_t bits);

    std::uint64_t key_;
    std::uint64_t counter_ = 0;
};

}  // namespace sbsim::radio
