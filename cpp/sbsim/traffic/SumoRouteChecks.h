#pragma once

#include "sbsim/kernel/Export.h"

namespace sbsim::traffic {

/// SUMO's switch behind its option --ignore-route-errors (on unless the option is given). While
/// it is on, a vehicle SUMO cannot insert (no lane of its first edge lets it on) or cannot route
/// (a trip with no way to its end) stops the run; while it is off SUMO drops the first kind
/// before it departs and inserts the second on the route it has, each with a warning. sumo-gui
/// turns it off when its user closes a lane; sbsim does so while a CloseRoadEffect is active,
/// because SUMO makes a flow's vehicle and inserts it within one step, with no moment between
/// for sbsim to take it out. libsumo has no call for it: this is libsumocpp's own global.
SBSIM_API bool sumoRouteChecks();
SBSIM_API void setSumoRouteChecks(bool on);

}  // namespace sbsim::traffic
