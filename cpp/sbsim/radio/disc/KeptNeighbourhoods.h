#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "sbsim/kernel/DefaultInitAllocator.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/NeighbourGrid.h"

namespace sbsim::radio {

/// Each vehicle's neighbours within a radius, from lists kept across steps (molecular dynamics'
/// Verlet lists): a vehicle's list holds the vehicles within radius + skin of it at their
/// reference positions, and stays complete while no vehicle is more than half the skin from its
/// reference. Then a step only filters the kept lists by the exact distance, instead of a
/// grid query, a sort and the distances per sender: at 0.1 s steps a vehicle moves a few metres a
/// step, so a list lasts many steps.
///
/// Answers are the grid's: within() gives the vehicles j != i with (xj - xi)² + (yj - yi)² <= r²
/// (NeighbourGrid's test), ascending, whatever the lists hold, with that square: its root is the
/// bits of (positions.col(j) - positions.col(i)).norm(), so a caller gathers no position again.
///
/// Vehicles are known across steps by a key (any stable, dense number per vehicle id: the medium's
/// station index). A vehicle that comes during an epoch takes its first position as its
/// reference, and one that moved more than half the skin from its reference takes its position as
/// its new one: the lists find both through a short list of newcomers. All lists start again (an
/// epoch) when that list grows long.
class SBSIM_API KeptNeighbourhoods {
public:
    using Index = traffic::NeighbourGrid::Index;
    using Key = std::uint32_t;
    /// A neighbour list: grown without a zero-fill (within() writes every candidate, keeps some).
    using Indices = std::vector<Index, kernel::DefaultInitAllocator<Index>>;
    /// Squared distances, one per neighbour of an Indices.
    using Squares = std::vector<double, kernel::DefaultInitAllocator<double>>;

    /// Lists of `radius` + `skin` m (skin > 0, finite; else std::invalid_argument).
    KeptNeighbourhoods(double radius, double skin);
    double radius() const { return radius_; }
    double skin() const { return skin_; }

    /// Follows the vehicles of a new step: `positions` (kept by reference until the next update)
    /// and their `keys` (as positions' columns; the same vehicle, the same key, across steps).
    /// `idsChanged`: false only when the keys are those of the last update.
    void update(const Eigen::Matrix2Xd& positions, std::span<const Key> keys, bool idsChanged);

    /// Appends to `out` the vehicles j != i within radius() of vehicle i, ascending, and to
    /// `squared` (as long as `out` on entry) each one's (xj - xi)² + (yj - yi)².
    void within(Index i, Indices& out, Squares& squared);

    /// Epochs started so far (for tests and figures).
    std::uint64_t epochs() const { return epochs_; }
    /// Whether the lists pay: the last finished epoch lasted at least `updates` updates (vehicles
    /// that move far each step, as at 1 s steps, restart them at nearly every step: a grid query
    /// per sender is then cheaper). True until an epoch has finished.
    bool lasting(std::uint64_t updates) const { return lastEpochUpdates_ == 0 || lastEpochUpdates_ >= updates; }

private:
    struct List {
        std::uint64_t epoch = 0;         // 0: none
        std::vector<Index> epochOthers;  // reference indices, ascending
        std::vector<Key> newcomers;      // newcomers within reach of this one's reference
        std::size_t newcomersSeen = 0;   // newcomers_ checked so far
    };
    void startEpoch();
    /// epochCurrent_ from epochToCurrent_ and the update's positions.
    void placeCurrent();
    /// Whether the references of `a` and `b` are within radius + skin.
    bool reachable(Key a, Key b) const;

    double radius_, skin_, reach_;
    const Eigen::Matrix2Xd* positions_ = nullptr;
    std::span<const Key> keys_;
    std::uint64_t epochs_ = 0;
    std::uint64_t epochUpdates_ = 0;      // updates in the current epoch
    std::uint64_t lastEpochUpdates_ = 0;  // in the last finished one
    // The epoch's reference: the positions and keys of the vehicles at its start, indexed by a grid.
    Eigen::Matrix2Xd epochPositions_;
    std::vector<Key> epochKeys_;
    traffic::NeighbourGrid epochGrid_;
    std::vector<Index> epochToCurrent_;  // per reference index, its current index, or -1 (gone)
    /// Per reference index, its vehicle's current position and index (NaN and -1: gone or moved),
    /// set at each update: a list's candidate is one read, not an index and then a position.
    struct Candidate {
        double x, y;
        Index j;
    };
    std::vector<Candidate> epochCurrent_;
    // Per key: its reference position (set: hasReference_), and its current index (or -1).
    std::vector<double> referenceX_, referenceY_;
    std::vector<unsigned char> hasReference_;
    std::vector<unsigned char> moved_;  // took a new reference during the epoch (then among the newcomers)
    std::vector<std::pair<Key, Index>> epochKeysSorted_;  // (key, reference index), by key
    std::vector<Index> keyToCurrent_;
    std::vector<Key> newcomers_;  // keys that came during the epoch, in order of arrival
    std::vector<List> lists_;     // by key
    /// The current indices of the epoch's vehicles still in place ascend with their epoch indices
    /// (the vehicles keep their order in the positions, whatever their keys: bench5k's station
    /// indices do not ascend in the snapshot's order): a list's answer needs no check of its order.
    /// Found at each update.
    bool ascending_ = false;
    std::vector<std::pair<Index, double>> tail_;  // within()'s newcomers in range, and its unsorted case
};

}  // namespace sbsim::radio
