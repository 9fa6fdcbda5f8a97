#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include "sbsim/kernel/RandomStream.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"

namespace py = pybind11;

namespace sbsim::storyboard {

using kernel::SimTime;

void bindTypes(py::module_& m) {
    py::class_<SimTime>(m, "SimTime")
        .def(py::init([](const py::object& seconds) { return toSimTime(seconds, "SimTime"); }),
             py::arg("seconds") = 0.0)
        .def_property_readonly("seconds", &SimTime::seconds)
        .def("__float__", &SimTime::seconds)
        .def("__add__", [](const SimTime& a, const py::object& b) { return a + toSimTime(b, "operand"); })
        .def("__radd__", [](const SimTime& a, const py::object& b) { return toSimTime(b, "operand") + a; })
        .def("__sub__", [](const SimTime& a, const py::object& b) { return a - toSimTime(b, "operand"); })
        .def("__rsub__", [](const SimTime& a, const py::object& b) { return toSimTime(b, "operand") - a; })
        .def("__eq__",
             [](const SimTime& a, const py::object& b) { return py::isinstance<SimTime>(b) && a == b.cast<SimTime>(); })
        .def("__lt__", [](const SimTime& a, const py::object& b) { return a < toSimTime(b, "operand"); })
        .def("__le__", [](const SimTime& a, const py::object& b) { return a <= toSimTime(b, "operand"); })
        .def("__gt__", [](const SimTime& a, const py::object& b) { return a > toSimTime(b, "operand"); })
        .def("__ge__", [](const SimTime& a, const py::object& b) { return a >= toSimTime(b, "operand"); })
        .def("__hash__", [](const SimTime& t) { return std::hash<SimTime::rep>()(t.raw()); })
        .def("__repr__", [](const SimTime& t) { return "SimTime(" + t.str() + ")"; });

    py::class_<Coord>(m, "Coord")
        .def(py::init([](const py::object& x, const py::object& y) {
                 return Coord{toNumber(x, "x"), toNumber(y, "y")};
             }),
             py::arg("x"), py::arg("y"))
        .def_readonly("x", &Coord::x)
        .def_readonly("y", &Coord::y)
        .def("__repr__", [](const Coord& c) {
            return "Coord(" + py::repr(py::float_(c.x)).cast<std::string>() + ", " +
                   py::repr(py::float_(c.y)).cast<std::string>() + ")";
        });

    py::class_<kernel::RandomStream, py::smart_holder>(m, "RandomNumberGenerator")
        .def_property_readonly("index", &kernel::RandomStream::index)
        .def(
            "uniform", [](kernel::RandomStream& r, double a, double b) { return r.uniform(a, b); }, py::arg("a") = 0.0,
            py::arg("b") = 1.0);
    m.attr("RNG") = m.attr("RandomNumberGenerator");  // Artery's name for the generator type
}

}  // namespace sbsim::storyboard
