#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio {

/// Buildings that attenuate the links crossing them, in Veins' simple obstacle model: a link
/// loses `perWallDb` for every wall (polygon edge) it crosses plus `perMetreDb` for every metre
/// it runs inside. The buildings are found through an R-tree of their bounding boxes (Boost
/// Geometry), so a link costs the few buildings near its line, not all of a city's. Thread-safe
/// to query once built.
class SBSIM_API Obstacles {
public:
    using Shape = std::vector<Eigen::Vector2d>;
    struct Crossing {
        int walls = 0;
        double insideMetres = 0;
    };

    Obstacles(double perWallDb, double perMetreDb);
    ~Obstacles();
    Obstacles(Obstacles&&) noexcept;
    Obstacles& operator=(Obstacles&&) noexcept;

    /// Adds a building outline (closed or not; at least 3 points, else ignored).
    void add(Shape shape);
    std::size_t size() const;
    double perWallDb() const { return perWallDb_; }
    double perMetreDb() const { return perMetreDb_; }

    /// Walls crossed and metres inside, over every building, on the straight line from a to b.
    Crossing crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
    /// The loss in dB of the link from a to b.
    double lossDb(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

private:
    struct Index;
    double perWallDb_, perMetreDb_;
    std::vector<Shape> shapes_;
    std::unique_ptr<Index> index_;
};

}  // namespace sbsim::radio
