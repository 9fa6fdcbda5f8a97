#include "sbsim/python/SnapshotView.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace sbsim::python {

namespace {

/// A read-only numpy copy of `n` rows of `columns` doubles at `data`.
py::array copy(const double* data, py::ssize_t n, py::ssize_t columns) {
    py::array out = columns == 1 ? py::array(py::dtype::of<double>(), {n}, {}, data)
                                 : py::array(py::dtype::of<double>(), {n, columns}, {}, data);
    out.attr("setflags")(py::arg("write") = false);
    return out;
}

const traffic::VehicleSnapshot& current(const traffic::VehicleSnapshot* snapshot, const StepValidity& valid,
                                        const char* what) {
    if (!valid || !*valid) {
        throw py::value_error(std::string("storyboard: this ") + what +
                              " belongs to an earlier step; read what you need during the call it is passed to");
    }
    return *snapshot;
}

const traffic::VehicleSnapshot& snap(const VehicleView& v) { return current(v.snapshot, v.valid, "Vehicle"); }
const traffic::VehicleSnapshot& snap(const SnapshotView& s) { return current(s.snapshot, s.valid, "Snapshot"); }

using Col = traffic::SnapshotColumns;
/// The snapshot, if it holds `column`: it reads only what the run's conditions declared.
template <typename View>
const traffic::VehicleSnapshot& holding(const View& view, Col::Column column) {
    const traffic::VehicleSnapshot& s = snap(view);
    if (!s.columns().contains(column)) {
        throw py::value_error("storyboard: the snapshot holds no '" + Col(column).str() +
                              "' in this run; name it in your condition's `columns`");
    }
    return s;
}

/// A per-vehicle column of the snapshot, copied on first access in the call.
template <const Eigen::VectorXd& (traffic::VehicleSnapshot::*Column)() const>
py::object column(SnapshotView& self, const char* name, Col::Column held) {
    const auto& s = holding(self, held);
    if (!self.columns.contains(name)) self.columns[name] = copy((s.*Column)().data(), s.size(), 1);
    return self.columns[name];
}

}  // namespace

void bindSnapshotView(py::module_& m) {
    py::class_<VehicleView>(m, "Vehicle")
        .def_property_readonly("id", [](const VehicleView& v) { return snap(v).ids()[v.index]; })
        .def_property_readonly("index", [](const VehicleView& v) { return v.index; })
        .def_property_readonly("x",
                               [](const VehicleView& v) { return holding(v, Col::Position).positions()(0, v.index); })
        .def_property_readonly("y",
                               [](const VehicleView& v) { return holding(v, Col::Position).positions()(1, v.index); })
        .def_property_readonly("position",
                               [](const VehicleView& v) {
                                   return py::make_tuple(holding(v, Col::Position).positions()(0, v.index),
                                                         holding(v, Col::Position).positions()(1, v.index));
                               })
        .def_property_readonly("speed", [](const VehicleView& v) { return holding(v, Col::Speed).speeds()[v.index]; })
        .def_property_readonly("angle", [](const VehicleView& v) { return holding(v, Col::Angle).angles()[v.index]; })
        .def_property_readonly(
            "acceleration", [](const VehicleView& v) { return holding(v, Col::Acceleration).accelerations()[v.index]; })
        .def_property_readonly("length", [](const VehicleView& v) { return holding(v, Col::Size).lengths()[v.index]; })
        .def_property_readonly("width", [](const VehicleView& v) { return holding(v, Col::Size).widths()[v.index]; })
        .def_property_readonly("max_speed",
                               [](const VehicleView& v) { return holding(v, Col::MaxSpeed).maxSpeeds()[v.index]; })
        .def_property_readonly("road", [](const VehicleView& v) { return holding(v, Col::Lane).roadId(v.index); })
        .def_property_readonly("lane", [](const VehicleView& v) { return holding(v, Col::Lane).laneId(v.index); })
        .def_property_readonly("type", [](const VehicleView& v) { return holding(v, Col::Type).typeId(v.index); })
        .def_property_readonly("time", [](const VehicleView& v) { return snap(v).time().seconds(); })
        .def("__repr__", [](const VehicleView& v) { return "<Vehicle " + snap(v).ids()[v.index] + ">"; });

    py::class_<SnapshotView>(m, "Snapshot")
        .def_property_readonly("time", [](const SnapshotView& s) { return snap(s).time().seconds(); })
        .def("__len__", [](const SnapshotView& s) { return snap(s).size(); })
        .def_property_readonly("ids", [](const SnapshotView& s) { return snap(s).ids(); })
        .def(
            "index_of", [](const SnapshotView& s, const std::string& id) { return snap(s).indexOf(id); }, py::arg("id"))
        .def_property_readonly("positions",
                               [](SnapshotView& self) -> py::object {
                                   const auto& s = holding(self, Col::Position);
                                   // Eigen keeps positions column-major 2 x N: one vehicle's x, y adjacent.
                                   if (!self.columns.contains("positions"))
                                       self.columns["positions"] = copy(s.positions().data(), s.size(), 2);
                                   return self.columns["positions"];
                               })
        .def_property_readonly(
            "speeds",
            [](SnapshotView& s) { return column<&traffic::VehicleSnapshot::speeds>(s, "speeds", Col::Speed); })
        .def_property_readonly(
            "angles",
            [](SnapshotView& s) { return column<&traffic::VehicleSnapshot::angles>(s, "angles", Col::Angle); })
        .def_property_readonly("accelerations",
                               [](SnapshotView& s) {
                                   return column<&traffic::VehicleSnapshot::accelerations>(s, "accelerations",
                                                                                           Col::Acceleration);
                               })
        .def_property_readonly(
            "lengths",
            [](SnapshotView& s) { return column<&traffic::VehicleSnapshot::lengths>(s, "lengths", Col::Size); })
        .def_property_readonly(
            "widths", [](SnapshotView& s) { return column<&traffic::VehicleSnapshot::widths>(s, "widths", Col::Size); })
        .def_property_readonly("max_speeds", [](SnapshotView& s) {
            return column<&traffic::VehicleSnapshot::maxSpeeds>(s, "max_speeds", Col::MaxSpeed);
        });
}

}  // namespace sbsim::python
