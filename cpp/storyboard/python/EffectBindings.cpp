#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include "sbsim/storyboard/effects/EmergencyStopEffect.h"
#include "sbsim/storyboard/effects/SignalEffect.h"
#include "sbsim/storyboard/effects/SpeedEffect.h"
#include "sbsim/storyboard/effects/StopEffect.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/PythonEffect.h"

namespace py = pybind11;

namespace sbsim::storyboard {

void bindEffects(py::module_& m) {
    py::class_<Effect, PythonEffect, py::smart_holder>(m, "Effect").def(py::init<>()).doc() =
        "Base of custom effects: override apply(self, vehicle) and remove(self, vehicle); "
        "vehicle is a VehicleController.";
    py::class_<SpeedEffect, Effect, py::smart_holder>(m, "SpeedEffect")
        .def(py::init([](const py::object& mps) {
                 return std::make_shared<SpeedEffect>(toNumber(mps, "SpeedEffect speed"));
             }),
             py::arg("mps"))
        .def_property_readonly("speed", &SpeedEffect::speed);
    py::class_<StopEffect, Effect, py::smart_holder>(m, "StopEffect").def(py::init<>());
    py::class_<EmergencyStopEffect, Effect, py::smart_holder>(m, "EmergencyStopEffect").def(py::init<>());
    py::class_<SignalEffect, Effect, py::smart_holder>(m, "SignalEffect")
        .def(py::init<std::string>(), py::arg("cause"))
        .def_property_readonly("cause", &SignalEffect::cause);
    // Artery's older factory names.
    m.attr("SpeedEffectFactory") = m.attr("SpeedEffect");
    m.attr("StopEffectFactory") = m.attr("StopEffect");
    m.attr("SignalEffectFactory") = m.attr("SignalEffect");
}

}  // namespace sbsim::storyboard
