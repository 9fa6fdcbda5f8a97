#include "sbsim/storyboard/python/Bindings.h"

#include <pybind11/stl.h>

#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/python/ArgumentConversions.h"
#include "sbsim/storyboard/python/ScriptContext.h"

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

}  // namespace

void bindBoard(py::module_& m) {
    py::class_<Story, py::smart_holder>(m, "Story")
        .def(py::init([](ConditionPtr condition, const py::object& effects, std::optional<std::string> name,
                         const py::object& maxActivations) {
                 if (!condition) throw py::type_error("Story needs a condition, got None");
                 std::vector<EffectPtr> list;
                 if (!effects.is_none()) {
                     for (const py::handle e : py::iter(effects)) {
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
                     const long long n = maxActivations.cast<long long>();
                     if (n < 1) throw py::value_error("Story max_activations must be >= 1, got " + std::to_string(n));
                     limit = static_cast<std::uint64_t>(n);
                 }
                 return std::make_shared<Story>(std::move(condition), std::move(list), std::move(name), limit);
             }),
             py::arg("condition"), py::arg("effects") = py::none(), py::arg("name") = py::none(),
             py::arg("max_activations") = py::none())
        .def_property_readonly("max_activations", &Story::maxActivations)
        .def_property_readonly("name", &Story::name)
        .def_property_readonly("activations", &Story::activations);

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
    py::class_<BoardHandle>(m, "Storyboard")
        .def("registerStory", registerStory, py::arg("story"))
        .def("register_story", registerStory, py::arg("story"))
        .def("getRandomNumberGenerator", randomGenerator, py::arg("k") = 0)
        .def("random_generator", randomGenerator, py::arg("k") = 0)
        .def("getWarmupEndTime", [](const BoardHandle& h) { return h.board().warmupEndTime(); })
        .def_property_readonly("warmup_end_time", [](const BoardHandle& h) { return h.board().warmupEndTime(); })
        .def("convertTraciPosition", convert, py::arg("x"), py::arg("y"))
        .def("convert_traci_position", convert, py::arg("x"), py::arg("y"))
        .def_property_readonly("stories", [](const BoardHandle& h) { return h.board().stories(); });
    m.def("_board", [] { return BoardHandle{}; });
}

}  // namespace sbsim::storyboard
