#pragma once

#include <string_view>

#include "sbsim/storyboard/geometry/Footprint.h"

namespace sbsim::storyboard::geometry {

/// How OpenSCENARIO's distance conditions measure: in the ego's frame, along its heading
/// (longitudinal), across it (lateral) or straight (cartesian).
enum class DistanceKind { Longitudinal, Lateral, Cartesian };

std::string_view distanceKindName(DistanceKind kind);

/// The distance between two outlines (0 where they overlap); a footprint of no length and width is a point.
double gap(const Footprint& a, const Footprint& b);

/// The distance from `ego` to `target` by `kind`: between their centres, or with `freespace`
/// between their outlines.
double distanceBetween(const Footprint& ego, const Footprint& target, DistanceKind kind, bool freespace);

}  // namespace sbsim::storyboard::geometry
