#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include "sbsim/storyboard/VehicleHandle.h"

namespace py = pybind11;

namespace sbsim::storyboard {

void bindVehicles(py::module_& m) {
    // Scripts may keep it: a handle, not the controller, which is gone when the vehicle leaves.
    py::register_exception<VehicleGone>(m, "VehicleGoneError", PyExc_RuntimeError);
    py::class_<VehicleHandle, py::smart_holder>(m, "VehicleController")
        .def_property_readonly("id", &VehicleHandle::id)
        .def_property_readonly("alive", &VehicleHandle::alive)
        .def_property_readonly("type_id", &VehicleHandle::typeId)
        .def_property_readonly("road_id", &VehicleHandle::roadId)
        .def_property_readonly("lane_id", &VehicleHandle::laneId)
        .def_property_readonly("lane_index", &VehicleHandle::laneIndex)
        .def_property_readonly("speed", &VehicleHandle::speed)
        .def_property_readonly("max_speed", &VehicleHandle::maxSpeed)
        .def_property_readonly("speed_mode", &VehicleHandle::speedMode)
        .def("set_max_speed", &VehicleHandle::setMaxSpeed, py::arg("mps"))
        .def("set_speed", &VehicleHandle::setSpeed, py::arg("mps"))
        .def("slow_down", &VehicleHandle::slowDown, py::arg("mps"), py::arg("seconds"))
        .def("set_speed_mode", &VehicleHandle::setSpeedMode, py::arg("mode"))
        .def("change_lane", &VehicleHandle::changeLane, py::arg("lane_index"), py::arg("seconds"));
}

}  // namespace sbsim::storyboard
