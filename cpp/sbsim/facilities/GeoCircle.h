#pragma once

#include "sbsim/radio/geonet/GeoArea.h"

namespace sbsim::facilities {

/// A geo-broadcast destination area (GeoNetworking's circle), in SUMO's network frame (m): the
/// area a DENM's GeoNetworking header carries.
using GeoCircle = radio::geonet::GeoArea;

}  // namespace sbsim::facilities
