#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::traffic {

/// The points of interest the loaded SUMO knows: the `<poi>` elements of the configuration's
/// additional files (say, where roadside units stand), in SUMO's network frame.
class SBSIM_API SumoPois {
public:
    struct Poi {
        std::string id;
        std::string type;  ///< its `type` attribute, e.g. "rsu"
        Eigen::Vector2d position = Eigen::Vector2d::Zero();
    };
    /// Every POI with its type and position, ids ascending. Throws std::logic_error unless SUMO
    /// is loaded.
    static std::vector<Poi> all();
};

}  // namespace sbsim::traffic
