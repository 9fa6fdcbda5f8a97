#include "sbsim/traffic/SumoRouteChecks.h"

// SUMO declares this in microsim/MSGlobals.h, which the eclipse-sumo wheel does not ship; the
// member is exported by libsumocpp (nm -D: _ZN9MSGlobals12gCheckRoutesE), set from the option
// when SUMO loads and read at every insertion and routing.
class MSGlobals {
public:
    static bool gCheckRoutes;
};

namespace sbsim::traffic {

bool sumoRouteChecks() { return MSGlobals::gCheckRoutes; }
void setSumoRouteChecks(bool on) { MSGlobals::gCheckRoutes = on; }

}  // namespace sbsim::traffic
