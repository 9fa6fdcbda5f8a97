#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "sbsim/kernel/DefaultInitAllocator.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/NeighbourGrid.h"

namespace sbsim::radio {

/// Every vehicle's neighbours of one step at once, when (nearly) every vehicle sends in the step:
/// one sweep takes each pair once, its distance computed once for both ends, instead of a grid
/// query, an ordering and the distances per sender.
///
/// Answers are a grid query's: others(i) are the vehicles j != i that NeighbourGrid::forEachWithin
/// visits, ascending, and distances(i) their (positions(j) - positions(i)).norm(), the same bits
/// whichever end computed them (a - b is exactly -(b - a)).
class SBSIM_API StepNeighbourhoods {
public:
    using Index = traffic::NeighbourGrid::Index;

    /// Every vehicle's neighbours within `radius` in `grid` (built over `positions`).
    void build(const traffic::NeighbourGrid& grid, const Eigen::Matrix2Xd& positions, double radius);

    std::size_t size() const { return start_.empty() ? 0 : start_.size() - 1; }
    std::span<const Index> others(Index i) const {
        const auto u = static_cast<std::size_t>(i);
        return {others_.data() + start_[u], others_.data() + start_[u + 1]};
    }
    std::span<const double> distances(Index i) const {
        const auto u = static_cast<std::size_t>(i);
        return {distance_.data() + start_[u], distance_.data() + start_[u + 1]};
    }

private:
    template <typename T>
    using Column = std::vector<T, kernel::DefaultInitAllocator<T>>;
    // The sweep's half: per vehicle i (ascending), its neighbours j > i, ascending, and how many
    // neighbours each vehicle has below it.
    std::vector<std::uint64_t> marks_;
    Column<std::size_t> aboveStart_;
    Column<Index> aboveOthers_;
    Column<double> aboveDistance_;
    Column<std::uint32_t> below_;
    // The rows: vehicle i's neighbours below it (filled in ascending order as the sweep's i
    // ascends), then those above it.
    Column<std::size_t> start_;
    Column<std::size_t> cursor_;
    Column<Index> others_;
    Column<double> distance_;
};

}  // namespace sbsim::radio
