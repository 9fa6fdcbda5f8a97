#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::traffic {

/// The polygons the loaded SUMO knows: the `<poly>` elements of the configuration's additional
/// files (say, a district drawn in netedit), in SUMO's network frame.
class SBSIM_API SumoPolygons {
public:
    /// The polygons' ids, ascending. Throws std::logic_error unless SUMO is loaded.
    static std::vector<std::string> ids();
    /// The shape of polygon `id` as SUMO stores it (a closed one repeats its first point).
    /// Throws std::invalid_argument with unknownMessage() for an id SUMO does not know, and
    /// std::logic_error unless SUMO is loaded.
    static std::vector<Eigen::Vector2d> shape(const std::string& id);
    struct Polygon {
        std::string id;
        std::string type;  ///< its `type` attribute, e.g. "building"
        std::vector<Eigen::Vector2d> shape;
    };
    /// Every polygon with its type and shape, ids ascending (one pass: a city has tens of
    /// thousands). Throws std::logic_error unless SUMO is loaded.
    static std::vector<Polygon> all();
    /// "SUMO has no polygon 'x' (...)", naming what `known` holds: all ids if few, else some.
    static std::string unknownMessage(const std::string& id, const std::vector<std::string>& known);

    /// How many known ids unknownMessage() names at most.
    static constexpr std::size_t kNamedIds = 10;
};

}  // namespace sbsim::traffic
