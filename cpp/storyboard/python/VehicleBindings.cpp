#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include "sbsim/traffic/VehicleController.h"

namespace py = pybind11;

namespace sbsim::storyboard {

using traffic::VehicleController;

void bindVehicles(py::module_& m) {
    py::class_<VehicleController, py::smart_holder>(m, "VehicleController")
        .def_property_readonly("id", &VehicleController::id)
        .def_property_readonly("type_id", &VehicleController::typeId)
        .def_property_readonly("road_id", &VehicleController::roadId)
        .def_property_readonly("lane_id", &VehicleController::laneId)
        .def_property_readonly("lane_index", &VehicleController::laneIndex)
        .def_property_readonly("speed", &VehicleController::speed)
        .def_property_readonly("max_speed", &VehicleController::maxSpeed)
        .def_property_readonly("speed_mode", &VehicleController::speedMode)
        .def("set_max_speed", &VehicleController::setMaxSpeed, py::arg("mps"))
        .def("set_speed", &VehicleController::setSpeed, py::arg("mps"))
        .def("slow_down", &VehicleController::slowDown, py::arg("mps"), py::arg("seconds"))
        .def("set_speed_mode", &VehicleController::setSpeedMode, py::arg("mode"))
        .def("change_lane", &VehicleController::changeLane, py::arg("lane_index"), py::arg("seconds"));
}

}  // namespace sbsim::storyboard
