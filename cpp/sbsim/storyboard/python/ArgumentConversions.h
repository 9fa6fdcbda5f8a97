#pragma once

#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <optional>
#include <set>
#include <string>

#include "sbsim/kernel/SimTime.h"

namespace sbsim::storyboard {

/// Artery's Coord: a point in the canvas frame.
struct Coord {
    double x = 0;
    double y = 0;
};

// Arguments from story scripts, checked on the way into C++: a wrong type is a TypeError and a
// bad value a ValueError, each naming the argument (`what`), so the script's line gets the blame.

/// Seconds as SimTime from a SimTime or a plain number (Artery scripts pass both).
kernel::SimTime toSimTime(const pybind11::handle& value, const char* what);
/// A finite int or float (not a bool).
double toNumber(const pybind11::handle& value, const char* what);
/// Coord → SUMO via the canvas frame; a plain (x, y) pair is already SUMO's.
Eigen::Vector2d toSumoPoint(const pybind11::handle& point);
/// One vehicle id or an iterable of them.
std::set<std::string> toIdSet(const pybind11::handle& ids);
/// None, or a distance >= 0 m.
std::optional<double> optionalDistance(const pybind11::object& distance);

}  // namespace sbsim::storyboard
