#include "sbsim/storyboard/python/SnapshotView.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace sbsim::storyboard {

namespace {

/// A read-only numpy view of `n` doubles at `data` (stride in doubles).
py::array view(const double* data, py::ssize_t n, py::ssize_t columns, const py::handle& owner) {
    py::array out =
        columns == 1
            ? py::array(py::dtype::of<double>(), {n}, {static_cast<py::ssize_t>(sizeof(double))}, data, owner)
            : py::array(py::dtype::of<double>(), {n, columns},
                        {static_cast<py::ssize_t>(columns * sizeof(double)), static_cast<py::ssize_t>(sizeof(double))},
                        data, owner);
    out.attr("setflags")(py::arg("write") = false);
    return out;
}

const traffic::VehicleSnapshot& snap(const VehicleView& v) { return *v.snapshot; }

/// A per-vehicle column of the snapshot behind the SnapshotView `self`.
template <const Eigen::VectorXd& (traffic::VehicleSnapshot::*Column)() const>
py::array column(py::object self) {
    const auto& s = *self.cast<const SnapshotView&>().snapshot;
    return view((s.*Column)().data(), s.size(), 1, self);
}

}  // namespace

void bindSnapshotView(py::module_& m) {
    py::class_<VehicleView>(m, "Vehicle")
        .def_property_readonly("id", [](const VehicleView& v) { return snap(v).ids()[v.index]; })
        .def_property_readonly("index", [](const VehicleView& v) { return v.index; })
        .def_property_readonly("x", [](const VehicleView& v) { return snap(v).positions()(0, v.index); })
        .def_property_readonly("y", [](const VehicleView& v) { return snap(v).positions()(1, v.index); })
        .def_property_readonly("position",
                               [](const VehicleView& v) {
                                   return py::make_tuple(snap(v).positions()(0, v.index),
                                                         snap(v).positions()(1, v.index));
                               })
        .def_property_readonly("speed", [](const VehicleView& v) { return snap(v).speeds()[v.index]; })
        .def_property_readonly("angle", [](const VehicleView& v) { return snap(v).angles()[v.index]; })
        .def_property_readonly("acceleration", [](const VehicleView& v) { return snap(v).accelerations()[v.index]; })
        .def_property_readonly("length", [](const VehicleView& v) { return snap(v).lengths()[v.index]; })
        .def_property_readonly("width", [](const VehicleView& v) { return snap(v).widths()[v.index]; })
        .def_property_readonly("max_speed", [](const VehicleView& v) { return snap(v).maxSpeeds()[v.index]; })
        .def_property_readonly("road", [](const VehicleView& v) { return snap(v).roadId(v.index); })
        .def_property_readonly("lane", [](const VehicleView& v) { return snap(v).laneId(v.index); })
        .def_property_readonly("type", [](const VehicleView& v) { return snap(v).typeId(v.index); })
        .def_property_readonly("time", [](const VehicleView& v) { return snap(v).time().seconds(); })
        .def("__repr__", [](const VehicleView& v) { return "<Vehicle " + snap(v).ids()[v.index] + ">"; });

    py::class_<SnapshotView>(m, "Snapshot")
        .def_property_readonly("time", [](const SnapshotView& s) { return s.snapshot->time().seconds(); })
        .def("__len__", [](const SnapshotView& s) { return s.snapshot->size(); })
        .def_property_readonly("ids", [](const SnapshotView& s) { return s.snapshot->ids(); })
        .def(
            "index_of", [](const SnapshotView& s, const std::string& id) { return s.snapshot->indexOf(id); },
            py::arg("id"))
        .def_property_readonly("positions",
                               [](py::object self) {
                                   const auto& s = *self.cast<const SnapshotView&>().snapshot;
                                   return view(s.positions().data(), s.size(), 2, self);
                               })
        .def_property_readonly("speeds", &column<&traffic::VehicleSnapshot::speeds>)
        .def_property_readonly("angles", &column<&traffic::VehicleSnapshot::angles>)
        .def_property_readonly("accelerations", &column<&traffic::VehicleSnapshot::accelerations>)
        .def_property_readonly("lengths", &column<&traffic::VehicleSnapshot::lengths>)
        .def_property_readonly("widths", &column<&traffic::VehicleSnapshot::widths>)
        .def_property_readonly("max_speeds", &column<&traffic::VehicleSnapshot::maxSpeeds>);
}

}  // namespace sbsim::storyboard
