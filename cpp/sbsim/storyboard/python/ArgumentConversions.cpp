#include "sbsim/storyboard/python/ArgumentConversions.h"

#include <cmath>
#include <stdexcept>

#include "sbsim/storyboard/python/ScriptContext.h"

namespace py = pybind11;

namespace sbsim::storyboard {

using kernel::SimTime;

SimTime toSimTime(const py::handle& value, const char* what) {
    if (py::isinstance<SimTime>(value)) return value.cast<SimTime>();
    if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))) {
        throw py::type_error(std::string(what) + " must be a SimTime or a number of seconds, got " +
                             py::str(py::type::of(value).attr("__name__")).cast<std::string>());
    }
    const double seconds = value.cast<double>();
    if (!std::isfinite(seconds)) throw py::value_error(std::string(what) + " must be finite");
    return SimTime::fromSeconds(seconds);
}

double toNumber(const py::handle& value, const char* what) {
    if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))) {
        throw py::type_error(std::string(what) + " must be a number, got " +
                             py::str(py::type::of(value).attr("__name__")).cast<std::string>() + " " +
                             py::repr(value).cast<std::string>());
    }
    const double v = value.cast<double>();
    if (!std::isfinite(v)) throw py::value_error(std::string(what) + " must be finite");
    return v;
}

Eigen::Vector2d toSumoPoint(const py::handle& point) {
    if (py::isinstance<Coord>(point)) {
        const Coord c = point.cast<Coord>();
        return ScriptContext::current().frame.toSumo({c.x, c.y});
    }
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(point);
    if (!py::isinstance<py::sequence>(point) || py::len(pair) != 2) {
        throw py::type_error("polygon points must be storyboard.Coord or (x, y) pairs, got " +
                             py::repr(point).cast<std::string>());
    }
    return {toNumber(pair[0], "x"), toNumber(pair[1], "y")};
}

std::set<std::string> toIdSet(const py::handle& ids) {
    if (py::isinstance<py::str>(ids)) return {ids.cast<std::string>()};
    std::set<std::string> out;
    for (const py::handle id : py::iter(ids)) {
        if (!py::isinstance<py::str>(id))
            throw py::type_error("vehicle ids must be strings, got " + py::repr(id).cast<std::string>());
        out.insert(id.cast<std::string>());
    }
    return out;
}

std::optional<double> optionalDistance(const py::object& distance) {
    if (distance.is_none()) return std::nullopt;
    const double d = toNumber(distance, "distance");
    if (d < 0) throw py::value_error("distance must be >= 0 m");
    return d;
}

}  // namespace sbsim::storyboard
