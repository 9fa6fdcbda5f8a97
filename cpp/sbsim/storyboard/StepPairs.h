#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/PairSweep.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

class EvaluationContext;

/// One sweep of a step's vehicle pairs shared by the conditions that answer every vehicle at once
/// from the pairs within their radius (TTC, speed difference with a distance). Each joins in its
/// prepare(); after every prepare() the board runs one traffic::PairSweep at the largest radius
/// joined, so a pair within several users' radii is found and its distance tested once, not once
/// per user (and the step's cells are sorted once). One user of the largest radius sweeps each row
/// itself (its pair test inlined in the sweep, as when it swept alone) and hands each pair on
/// (Handover::offer); the others are handed exactly the pairs within their own radius, row by row
/// on the pool. Each keeps what it wants of them and after the sweep gets all it kept, sorted.
class SBSIM_API StepPairs {
public:
    using Index = traffic::VehicleSnapshot::Index;
    using Pair = std::pair<Index, Index>;

    /// Where the user sweeping a row hands each pair on to the others.
    class Handover {
    public:
        /// Pair (a, b) at squared distance d2 (PairSweep's, within the sweep's radius): appended
        /// to the pairs of every other user's radius it is within.
        void offer(Index a, Index b, double d2) {
            // Inline only the one test most pairs end on (beyond the largest other radius), so
            // the sweeping user's loop stays as tight as when it swept alone.
            if (levels_ != 0 && d2 <= r2_[0]) hand(a, b, d2);
        }

    private:
        friend class StepPairs;
        /// offer() for a pair within the largest other radius: to every radius it is within.
        void hand(Index a, Index b, double d2);
        const double* r2_ = nullptr;  // the others' distinct radii squared, descending
        std::vector<Pair>* within_ = nullptr;
        std::size_t levels_ = 0;
    };

    class User {
    public:
        virtual ~User() = default;
        /// The radius (m) whose pairs this user takes: finite and >= 0.
        virtual double pairRadius() const = 0;
        /// As the user sweeping the rows (one of the largest radius): called on the pool once per
        /// row of `sweep`, rows in parallel (so: no shared writes). Visits the row's pairs
        /// (PairSweep::forEachPairInRow with the squared distance), offers each to `handover` and
        /// appends to `kept` what it keeps of it.
        virtual void sweepRow(const traffic::VehicleSnapshot& snapshot, const traffic::PairSweep& sweep,
                              std::size_t row, Handover& handover, std::vector<Pair>& kept) const = 0;
        /// As any other user: called on the pool once per row, rows in parallel, after the row
        /// was swept: appends to `kept` what the user keeps of `pairs`, every pair of the row
        /// within pairRadius() (dx·dx + dy·dy <= r·r), each once, either index first.
        virtual void keepPairs(const traffic::VehicleSnapshot& snapshot, std::span<const Pair> pairs,
                               std::vector<Pair>& kept) const = 0;
        /// After the sweep, on the calling thread: everything keepPairs() kept, sorted (the same
        /// whatever the thread count).
        virtual void pairsKept(const traffic::VehicleSnapshot& snapshot, const std::vector<Pair>& kept) = 0;
    };

    /// Adds `user` to the next run() (joining twice in a step counts once).
    void join(User& user);
    /// One sweep over ctx.snapshot() for the users who joined since the last run (on
    /// ctx.parallel(), or the calling thread without one); they leave, even if a user throws.
    void run(const EvaluationContext& ctx);

    /// Users waiting for the next run().
    std::size_t joined() const { return joined_; }
    /// Sweeps built since construction (runs with a user).
    std::size_t sweeps() const { return sweeps_; }

private:
    struct Slot {
        User* user = nullptr;
        std::size_t level = 0;                   // its radius in levelR2_ (not the first user's)
        std::vector<std::vector<Pair>> rowKept;  // what it kept per row (one writer per row)
        std::vector<Pair> kept;                  // all of it, sorted
    };
    std::vector<Slot> slots_;  // the first joined_ wait; the others keep their buffers for later steps
    std::size_t joined_ = 0;
    // The users after the first (who sweeps): their distinct radii squared, descending, and per
    // row the pairs within each, rows_[row][level].
    std::vector<double> levelR2_;
    std::vector<std::vector<std::vector<Pair>>> rows_;
    traffic::PairSweep sweep_;
    std::size_t sweeps_ = 0;
};

}  // namespace sbsim::storyboard
