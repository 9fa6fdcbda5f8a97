#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include <limits>
#include <variant>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/kernel/Statistics.h"
#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/WorldEffect.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/ScriptContext.h"
#include "sbsim/traffic/SumoPolygons.h"

namespace py = pybind11;

namespace sbsim::storyboard {

using kernel::SimTime;

namespace {

/// The `board` object scripts receive.
struct BoardHandle {
    Storyboard& board() const {
        Storyboard* b = ScriptContext::current().board;
        if (b == nullptr) throw std::runtime_error("the storyboard is only available while sbsim runs a story");
        return *b;
    }
};

/// `board.parameters`: the run's study parameters as a read-only mapping. Reading a value counts
/// as using it (the run warns about parameters never used).
struct ParametersView {
    const kernel::StudyParameters& parameters() const { return BoardHandle{}.board().simulation().parameters(); }
};

py::object toPython(const kernel::StudyParameters::Value& value) {
    return std::visit([](const auto& v) -> py::object { return py::cast(v); }, value);
}

py::object lookup(const kernel::StudyParameters& parameters, const std::string& name, const py::object& fallback) {
    const auto value = parameters.get(name);
    return value ? toPython(*value) : fallback;
}

}  // namespace

void bindBoard(py::module_& m) {
    py::class_<ParametersView>(m, "Parameters")
        .def("__getitem__",
             [](const ParametersView& p, const std::string& name) {
                 const auto value = p.parameters().get(name);
                 if (!value) throw py::key_error(name);
                 return toPython(*value);
             })
        .def(
            "get",
            [](const ParametersView& p, const std::string& name, const py::object& fallback) {
                return lookup(p.parameters(), name, fallback);
            },
            py::arg("name"), py::arg("default") = py::none())
        .def("__contains__",
             [](const ParametersView& p, const std::string& name) { return p.parameters().contains(name); })
        .def("__len__", [](const ParametersView& p) { return p.parameters().all().size(); })
        .def("__iter__",
             [](const ParametersView& p) {
                 py::list names;
                 for (const auto& [name, value] : p.parameters().all()) names.append(name);
                 return py::iter(names);
             })
        .def("keys",
             [](const ParametersView& p) {
                 py::list names;
                 for (const auto& [name, value] : p.parameters().all()) names.append(name);
                 return names;
             })
        .def("items",
             [](const ParametersView& p) {
                 py::list items;
                 for (const auto& [name, value] : p.parameters().all()) {
                     items.append(py::make_tuple(name, lookup(p.parameters(), name, py::none())));
                 }
                 return items;
             })
        .def("__repr__", [](const ParametersView& p) {
            std::string out = "Parameters({";
            for (const auto& [name, value] : p.parameters().all()) {
                if (out.back() != '{') out += ", ";
                out += py::repr(py::str(name)).cast<std::string>() + ": " + kernel::StudyParameters::format(value);
            }
            return out + "})";
        });

    py::class_<Story, py::smart_holder>(m, "Story")
        .def(py::init([](ConditionPtr condition, const py::object& effects, std::optional<std::string> name,
                         const py::object& maxActivations) {
                 if (!condition) throw py::type_error("Story needs a condition, got None");
                 std::vector<EffectPtr> list;
                 if (!effects.is_none()) {
                     for (const py::handle e : py::iter(effects)) {
                         if (py::isinstance<WorldEffect>(e)) {
                             throw py::type_error("Story effects act on vehicles; " + py::repr(e).cast<std::string>() +
                                                  " is a world effect: put it in a WorldStory");
                         }
                         if (!py::isinstance<Effect>(e)) {
                             throw py::type_error("Story effects must be storyboard effects, got " +
                                                  py::repr(e).cast<std::string>());
                         }
                         list.push_back(e.cast<EffectPtr>());
                     }
                 }
                 std::optional<std::uint64_t> limit;
                 if (!maxActivations.is_none()) {
                     if (!py::isinstance<py::int_>(maxActivations) || py::isinstance<py::bool_>(maxActivations)) {
                         throw py::type_error("Story max_activations must be a whole number, got " +
                                              py::repr(maxActivations).cast<std::string>());
                     }
                     int overflow = 0;  // a Python int may exceed 64 bits: name the range, not the cast
                     const long long n = PyLong_AsLongLongAndOverflow(maxActivations.ptr(), &overflow);
                     if (overflow != 0 || n < 1) {
                         throw py::value_error("Story max_activations must be from 1 to " +
                                               std::to_string(std::numeric_limits<long long>::max()) + ", got " +
                                               py::repr(maxActivations).cast<std::string>());
                     }
                     limit = static_cast<std::uint64_t>(n);
                 }
                 return std::make_shared<Story>(std::move(condition), std::move(list), std::move(name), limit);
             }),
             py::arg("condition"), py::arg("effects") = py::none(), py::arg("name") = py::none(),
             py::arg("max_activations") = py::none())
        .def_property_readonly("max_activations", &Story::maxActivations)
        .def_property_readonly("name", &Story::name)
        .def_property_readonly("activations", [](const Story& s) { return s.counters().activations(); });

    const auto registerStory = [](const BoardHandle& h, StoryPtr story) {
        if (!story) throw py::type_error("registerStory needs a Story, got None");
        h.board().registerStory(std::move(story));
    };
    const auto randomGenerator = [](const BoardHandle& h, int k) {
        if (k < 0) throw py::value_error("the generator index must be >= 0");
        return h.board().randomStream(static_cast<unsigned>(k));
    };
    const auto convert = [](const BoardHandle&, double x, double y) {
        const Eigen::Vector2d c = ScriptContext::current().frame.toCanvas({x, y});
        return Coord{c.x(), c.y()};
    };
    // A row of the run's statistics (--statistics) at the current time: from the story named, or
    // the storyboard; of the vehicle named, or of none.
    const auto record = [](const BoardHandle& h, const std::string& name, double value,
                           const std::optional<std::string>& vehicle, const std::optional<std::string>& story) {
        Storyboard& board = h.board();
        kernel::Statistics* statistics = board.statistics();
        if (statistics == nullptr) throw std::runtime_error("board.record: this run records no statistics");
        try {
            statistics->record(vehicle.value_or(""), story.value_or("storyboard"), name, board.simulation().now(),
                               value);
        } catch (const std::invalid_argument& e) {
            throw py::value_error(std::string("board.record: ") + e.what());
        }
    };
    const auto registerCriterion = [](const BoardHandle& h, CriterionPtr criterion, std::optional<std::string> name) {
        if (!criterion) throw py::type_error("registerCriterion needs a Criterion, got None");
        if (name) criterion->setName(std::move(*name));
        h.board().registerCriterion(std::move(criterion));
    };
    py::class_<BoardHandle>(m, "Storyboard")
        .def("registerCriterion", registerCriterion, py::arg("criterion"), py::arg("name") = py::none())
        .def("register_criterion", registerCriterion, py::arg("criterion"), py::arg("name") = py::none())
        .def("record", record, py::arg("name"), py::arg("value"), py::kw_only(), py::arg("vehicle") = py::none(),
             py::arg("story") = py::none())
        .def("registerStory", registerStory, py::arg("story"))
        .def("register_story", registerStory, py::arg("story"))
        .def("getRandomNumberGenerator", randomGenerator, py::arg("k") = 0)
        .def("random_generator", randomGenerator, py::arg("k") = 0)
        .def_property_readonly("parameters", [](const BoardHandle&) { return ParametersView{}; })
        .def(
            "parameter",
            [](const BoardHandle& h, const std::string& name, const py::object& fallback) {
                return lookup(h.board().simulation().parameters(), name, fallback);
            },
            py::arg("name"), py::arg("default") = py::none())
        .def("getWarmupEndTime", [](const BoardHandle& h) { return h.board().warmupEndTime(); })
        .def_property_readonly("warmup_end_time", [](const BoardHandle& h) { return h.board().warmupEndTime(); })
        .def("convertTraciPosition", convert, py::arg("x"), py::arg("y"))
        .def("convert_traci_position", convert, py::arg("x"), py::arg("y"))
        .def_property_readonly("stories", [](const BoardHandle& h) { return h.board().stories(); });
    m.def("_board", [] { return BoardHandle{}; });
    // SUMO is loaded before any script runs (`sbsim check` too); an unknown id is a ValueError.
    m.def(
        "sumo_polygon",
        [](const std::string& polyId) {
            py::list points;
            for (const Eigen::Vector2d& p : traffic::SumoPolygons::shape(polyId))
                points.append(py::make_tuple(p.x(), p.y()));
            return points;
        },
        py::arg("poly_id"));
}

}  // namespace sbsim::storyboard
