#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include <limits>

#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/DeferringCondition.h"
#include "sbsim/storyboard/conditions/LikelihoodCondition.h"
#include "sbsim/storyboard/conditions/LimitCondition.h"
#include "sbsim/storyboard/conditions/OrCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/SpeedDifferenceCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/conditions/TtcCondition.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/PythonCondition.h"

namespace py = pybind11;

namespace sbsim::storyboard {

using kernel::SimTime;

namespace {

template <typename Condition, typename Class>
void bindSpeedDifference(Class&& cls) {
    cls.def(py::init([](const py::object& delta, const py::object& distance) {
                return std::make_shared<Condition>(toNumber(delta, "delta"), optionalDistance(distance));
            }),
            py::arg("delta"), py::arg("distance") = py::none());
}

}  // namespace

void bindConditions(py::module_& m) {
    py::class_<Condition, PythonCondition, py::smart_holder>(m, "Condition").def(py::init<>()).doc() =
        "Base of custom conditions: override test(self, vehicle) -> bool | set[str], or the "
        "vectorised test_all(self, snapshot) -> numpy bool array.";

    py::class_<TimeCondition, Condition, py::smart_holder>(m, "TimeCondition")
        .def(py::init([](const py::object& begin, const py::object& end) {
                 std::optional<SimTime> e;
                 if (!end.is_none()) e = toSimTime(end, "end");
                 return std::make_shared<TimeCondition>(toSimTime(begin, "begin"), e);
             }),
             py::arg("begin"), py::arg("end") = py::none());
    py::class_<SpeedConditionGreater, Condition, py::smart_holder>(m, "SpeedConditionGreater")
        .def(py::init(
                 [](const py::object& mps) { return std::make_shared<SpeedConditionGreater>(toNumber(mps, "speed")); }),
             py::arg("mps"));
    py::class_<SpeedConditionLess, Condition, py::smart_holder>(m, "SpeedConditionLess")
        .def(py::init(
                 [](const py::object& mps) { return std::make_shared<SpeedConditionLess>(toNumber(mps, "speed")); }),
             py::arg("mps"));
    py::class_<CarSetCondition, Condition, py::smart_holder>(m, "CarSetCondition")
        .def(py::init([](const py::object& ids) { return std::make_shared<CarSetCondition>(toIdSet(ids)); }),
             py::arg("ids"));
    py::class_<PolygonCondition, Condition, py::smart_holder>(m, "PolygonCondition")
        .def(py::init([](const py::iterable& points) {
                 std::vector<Eigen::Vector2d> vertices;
                 for (const py::handle p : points) vertices.push_back(toSumoPoint(p));
                 if (vertices.size() < 3) {
                     throw py::value_error("PolygonCondition needs 3 or more points, got " +
                                           std::to_string(vertices.size()));
                 }
                 return std::make_shared<PolygonCondition>(std::move(vertices));
             }),
             py::arg("points"));
    bindSpeedDifference<SpeedDifferenceConditionFaster>(
        py::class_<SpeedDifferenceConditionFaster, Condition, py::smart_holder>(m, "SpeedDifferenceConditionFaster"));
    bindSpeedDifference<SpeedDifferenceConditionSlower>(
        py::class_<SpeedDifferenceConditionSlower, Condition, py::smart_holder>(m, "SpeedDifferenceConditionSlower"));
    py::class_<TtcCondition, Condition, py::smart_holder>(m, "TtcCondition")
        .def(py::init([](const py::object& ttc, const py::object& distance) {
                 const double t = toNumber(ttc, "ttc");
                 const double d = toNumber(distance, "distance");
                 if (t <= 0) throw py::value_error("ttc must be > 0 s");
                 if (d < 0) throw py::value_error("distance must be >= 0 m");
                 return std::make_shared<TtcCondition>(t, d);
             }),
             py::arg("ttc"), py::arg("distance") = 100.0);
    py::class_<AndCondition, Condition, py::smart_holder>(m, "AndCondition")
        .def(py::init<ConditionPtr, ConditionPtr>(), py::arg("a"), py::arg("b"));
    py::class_<OrCondition, Condition, py::smart_holder>(m, "OrCondition")
        .def(py::init<ConditionPtr, ConditionPtr>(), py::arg("a"), py::arg("b"));
    py::class_<LimitCondition, Condition, py::smart_holder>(m, "LimitCondition")
        .def(py::init([](const py::object& n) {
                 if (!py::isinstance<py::int_>(n) || py::isinstance<py::bool_>(n)) {
                     throw py::type_error("LimitCondition needs a whole number of vehicles, got " +
                                          py::repr(n).cast<std::string>());
                 }
                 // Compared as Python ints: a count beyond 64 bits must not wrap into a small one.
                 if (n < py::int_(0) || n > py::int_(std::numeric_limits<std::int64_t>::max())) {
                     throw py::value_error("LimitCondition needs a count from 0 to 2**63-1, got " +
                                           py::repr(n).cast<std::string>());
                 }
                 return std::make_shared<LimitCondition>(n.cast<std::int64_t>());
             }),
             py::arg("n"));
    py::class_<LikelihoodCondition, Condition, py::smart_holder>(m, "LikelihoodCondition")
        .def(py::init([](std::shared_ptr<kernel::RandomStream> rng, const py::object& p) {
                 if (!rng) throw py::type_error("LikelihoodCondition needs a random number generator");
                 return std::make_shared<LikelihoodCondition>(std::move(rng), toNumber(p, "likelihood"));
             }),
             py::arg("rng"), py::arg("p"));
    py::class_<DeferringCondition, Condition, py::smart_holder>(m, "DeferringCondition")
        .def(py::init([](std::shared_ptr<kernel::RandomStream> rng, const py::object& min, const py::object& max) {
                 if (!rng) throw py::type_error("DeferringCondition needs a random number generator");
                 const SimTime lo = toSimTime(min, "min");
                 const SimTime hi = toSimTime(max, "max");
                 if (lo < SimTime::zero() || hi < lo) throw py::value_error("DeferringCondition needs 0 <= min <= max");
                 return std::make_shared<DeferringCondition>(std::move(rng), lo, hi);
             }),
             py::arg("rng"), py::arg("min"), py::arg("max"));
}

}  // namespace sbsim::storyboard
