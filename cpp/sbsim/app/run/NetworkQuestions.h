#pragma once

#include "sbsim/app/inputs/RouteIds.h"
#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/traffic/NetworkIds.h"

namespace sbsim::app {

/// Whether the loaded scenario has the edges, lanes, traffic lights and vehicle types stories name
/// (SUMO's network and types, and the route files' types): asked by `sbsim check`, which warns, and
/// by a run, which refuses a story naming an id that does not exist. Build it after SUMO loaded.
class NetworkQuestions {
public:
    explicit NetworkQuestions(RouteIds routes);

    /// Sets `scenario`'s network questions (edges, lanes, traffic lights, vehicle types) to this
    /// object's answers; it must outlive `scenario`'s use.
    void answer(storyboard::CheckScenario& scenario) const;

    const RouteIds& routes() const { return routes_; }

private:
    traffic::NetworkIds network_;
    RouteIds routes_;
};

}  // namespace sbsim::app
