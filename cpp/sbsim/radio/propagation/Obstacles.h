#pragma once

#include <Eigen/Core>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio {

/// Buildings that attenuate the links crossing them, in Veins' simple obstacle model: a link
/// loses `perWallDb` for every wall (polygon edge) it crosses plus `perMetreDb` for every metre
/// it runs inside. The buildings are pre-cut into a uniform grid of their bounding boxes, so a
/// link visits only the cells its line crosses and tests only the buildings listed there (their
/// box first, Veins PR #152's culling, then the walls). Thread-safe to query; add() must not run
/// concurrently with queries.
class SBSIM_API Obstacles {
public:
    using Shape = std::vector<Eigen::Vector2d>;
    struct Crossing {
        int walls = 0;
        double insideMetres = 0;
    };

    /// `cellMetres` the grid's cell side; 0: chosen from the buildings' sizes when the grid is built.
    Obstacles(double perWallDb, double perMetreDb, double cellMetres = 0);
    ~Obstacles();
    Obstacles(const Obstacles&) = delete;  // shared between the medium's threads, never copied
    Obstacles& operator=(const Obstacles&) = delete;

    /// Adds a building outline (closed or not; at least 3 points, else ignored).
    void add(Shape shape);
    std::size_t size() const;
    double perWallDb() const { return perWallDb_; }
    double perMetreDb() const { return perMetreDb_; }

    /// Walls crossed and metres inside, over every building, on the straight line from a to b:
    /// the buildings summed in the order they were added, so the result is exactly that of
    /// crossingEveryBuilding(); walked from the lesser end, so the same from either end.
    /// With `stopAtWalls`, the walk may stop once it has found that many walls: then the
    /// result has at least that many and its depth is partial (for a link whose walls alone put
    /// it below what counts, the rest of its loss changes nothing); with fewer, it is exact.
    Crossing crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b, int stopAtWalls = kNoStop) const;
    /// The same by walking every building's walls, no grid, no culling: the reference the grid
    /// must equal (tests and checks).
    Crossing crossingEveryBuilding(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
    /// The loss in dB of the link from a to b.
    double lossDb(const Eigen::Vector2d& a, const Eigen::Vector2d& b, int stopAtWalls = kNoStop) const;
    static constexpr int kNoStop = 1 << 30;

    /// Links asked for so far (crossing() and lossDb() calls): the run summary prints it.
    std::uint64_t linksEvaluated() const { return linksEvaluated_.load(std::memory_order_relaxed); }
    /// The grid's cell side in metres (after the first query or gridCellMetres() call).
    double gridCellMetres() const;

private:
    struct Grid;
    /// Building k's walls and depth along a→b, added to `total`; `ts` is scratch.
    void addCrossing(std::size_t k, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double length,
                     std::vector<double>& ts, Crossing& total) const;
    const Grid& grid() const;

    double perWallDb_, perMetreDb_, cellMetres_;
    std::vector<Eigen::Vector2d> points_;       // every outline, one after the other
    std::vector<std::uint32_t> firstPoint_;     // building k's points: [firstPoint_[k], firstPoint_[k + 1])
    std::vector<Eigen::Vector4d> boxes_;        // per building: min x, min y, max x, max y, widened by kMargin
    mutable std::unique_ptr<const Grid> grid_;  // built at the first query after an add()
    mutable std::atomic<bool> gridReady_{false};
    mutable std::mutex gridMutex_;
    mutable std::atomic<std::uint64_t> linksEvaluated_{0};
};

}  // namespace sbsim::radio
