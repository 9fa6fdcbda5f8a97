#pragma once

namespace sbsim::traffic {

/// A point in SUMO's network frame (m).
struct Position {
    double x = 0;
    double y = 0;
};

}  // namespace sbsim::traffic
