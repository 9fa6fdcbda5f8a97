#include "sbsim/facilities/GeoCircle.h"

namespace sbsim::facilities {

bool GeoCircle::contains(const Eigen::Vector2d& point) const {
    return (point - center).squaredNorm() <= radius * radius;
}

}  // namespace sbsim::facilities
