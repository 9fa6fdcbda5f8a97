#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/HugePageAllocator.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::radio {

/// Log-normal shadowing per pair of stations that moves with them (Gudmundson, Electronics Letters
/// 27(23), 1991; 3GPP TR 37.885 §6.2.3 for V2V): each pair has a standard normal z, its shadowing is
/// σ·z dB, and when its stations have moved Δd since the pair's last update
///     z ← ρ z + √(1 − ρ²) N,   ρ = exp(−Δd / d_corr),
/// so the autocorrelation over Δd metres is exp(−Δd / d_corr) and z stays standard normal.
/// Δd is the sum of both stations' displacements: two cars keeping their gap still drive past new
/// obstacles, and a parked pair keeps its value. The pair is unordered (a→b and b→a see the same
/// value, as the channel is reciprocal) and named by its stations' keys (CounterRandom::keyOf), not
/// by slots, so a pair's values do not depend on the order stations appeared.
///
/// Determinism: the n-th value of a pair is drawn from CounterRandom keyed by (seed, pair, n), and a
/// pair is updated only by the frames it carries, which the medium computes one after the other; so
/// values do not depend on --threads. pair() (which may insert) is serial; valueDb() on distinct
/// pairs may run on many threads at once.
///
/// Memory: a pair unseen for kForgetAfter (5 s: at 10 m/s the pair has moved 100 m, ρ < 0.001 for
/// the 10–25 m presets) is forgotten; seen again it starts afresh with an independent value.
class SBSIM_API CorrelatedShadowing {
public:
    using Index = std::uint32_t;
    static constexpr kernel::SimTime kForgetAfter = kernel::SimTime::fromMilliseconds(5'000);

    /// Throws std::invalid_argument unless σ >= 0 and d_corr > 0.
    CorrelatedShadowing(double sigmaDb, double correlationDistance, std::uint64_t seed);

    /// The pair of the stations keyed `a` and `b` (either order), made on first use; seen at `now`. Serial.
    Index pair(std::uint64_t a, std::uint64_t b, kernel::SimTime now);
    /// pair(a, others[k], now) for every k into `out`, the table's slots fetched ahead (a frame's
    /// hundreds of lookups are cache misses each). Serial.
    void pairs(std::uint64_t a, const std::vector<std::uint64_t>& others, kernel::SimTime now, std::vector<Index>& out);
    /// The pair (an index pair() gave) is seen at `now`: what pair() does to a pair it finds, for a
    /// caller that kept the index. Safe on distinct pairs at once.
    void touch(Index pair, kernel::SimTime now) { states_[pair].seen = now; }
    /// Counts the forget() sweeps that freed pairs: an index kept from an earlier generation may
    /// name another pair now.
    std::uint64_t generation() const { return generation_; }
    /// How many links ahead a caller walking a list of pairs prefetches the state of: a state is a
    /// DRAM miss (~100 ns) and a drawn link ~30 ns of work, so 4 ahead left most of the miss waiting.
    static constexpr std::size_t kPrefetchAhead = 16;
    /// Hints that valueDb(pair, …) comes soon.
    void prefetch(Index pair) const { __builtin_prefetch(&states_[pair], 1); }
    /// The pair's shadowing in dB with station `a` at (ax, ay) and `b` at (bx, by), after moving it
    /// on by their displacements since its last value. Safe on distinct pairs at once.
    double valueDb(Index pair, std::uint64_t a, double ax, double ay, std::uint64_t b, double bx, double by);
    /// Forgets the pairs unseen for kForgetAfter (a sweep at most every kForgetAfter). Serial.
    void forget(kernel::SimTime now);

    std::size_t pairs() const { return used_; }
    double correlationDistance() const { return correlationDistance_; }

private:
    struct Key {
        std::uint64_t lo, hi;
        bool operator==(const Key&) const = default;
    };
    static constexpr Index kEmpty = ~Index{0};
    /// A slot of the open-addressing table (linear probing, at most half full): looked up for
    /// every link of every frame, where a node-based map cost a quarter of the run.
    struct Slot {
        Key key{};
        Index index = kEmpty;
    };
    /// One record per pair: a frame reads and writes all of it at once, so its fields sit together,
    /// in one cache line of its own. (With its key, 80 bytes, every record straddled two lines and a
    /// drawn link paid two misses, one of them past the prefetch; the key is the callers' a and b.)
    struct alignas(64) State {
        double z = 0;
        std::uint64_t draws = 0;                    // values drawn so far: the next one's counter
        double loX = 0, loY = 0, hiX = 0, hiY = 0;  // where its stations were at its last value
        kernel::SimTime seen;                       // the last frame that carried it
        bool fresh = true;                          // no value yet
    };
    static_assert(sizeof(State) == 64, "a pair's state is one cache line");
    std::size_t slotOf(const Key& key) const;
    /// Lays the live slots out afresh in a table of `slots` (a power of two).
    void rebuild(std::size_t slots);

    double sigmaDb_, correlationDistance_;
    std::uint64_t seed_;
    // Both tables are read at random, a miss each: on huge pages, so the miss is not a TLB miss too.
    template <class T>
    using Table = std::vector<T, kernel::HugePageAllocator<T>>;
    Table<Slot> table_;
    std::size_t used_ = 0;
    Table<State> states_;
    std::vector<Index> free_;
    kernel::SimTime lastSweep_;
    std::uint64_t generation_ = 0;
};

}  // namespace sbsim::radio
