#include "sbsim/radio/geonet/GreedyForwarding.h"

namespace sbsim::radio::geonet {

std::optional<std::size_t> greedyNextHop(const Eigen::Vector2d& self, const Eigen::Vector2d& target,
                                         std::span<const Neighbour> neighbours) {
    double best = (self - target).squaredNorm();
    std::optional<std::size_t> choice;
    for (std::size_t k = 0; k < neighbours.size(); ++k) {
        const double d = (neighbours[k].position - target).squaredNorm();
        if (d < best) {
            best = d;
            choice = k;
        }
    }
    return choice;
}

}  // namespace sbsim::radio::geonet
