#include "sbsim/storyboard/python/StoryScript.h"

#include <pybind11/embed.h>

#include "sbsim/storyboard/StoryError.h"
#include "sbsim/storyboard/python/ScriptContext.h"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace sbsim::storyboard {

namespace {

/// How many parameters `f` declares, as len(inspect.signature(f).parameters). A plain function's
/// code object says it without importing inspect (and with it ast, dis, re, tokenize: 0.8 MB
/// resident that a run would carry to its end); other callables ask inspect.
std::size_t parameterCount(const py::object& f) {
    if (PyFunction_Check(f.ptr())) {
        const auto* code = reinterpret_cast<PyCodeObject*>(PyFunction_GetCode(f.ptr()));
        const int flags = code->co_flags;
        return static_cast<std::size_t>(code->co_argcount + code->co_kwonlyargcount + ((flags & CO_VARARGS) ? 1 : 0) +
                                        ((flags & CO_VARKEYWORDS) ? 1 : 0));
    }
    return py::len(py::module_::import("inspect").attr("signature")(f).attr("parameters"));
}

}  // namespace

StoryScript::StoryScript(python::PythonRuntime& python, const fs::path& script, Storyboard& board,
                         const CanvasFrame& frame)
    : script_(fs::absolute(script)), board_(board), frame_(frame), python_(python) {
    ScriptContext& context = ScriptContext::current();
    context.board = &board_;
    context.frame = frame_;
    context.script = script_;
}

StoryScript::~StoryScript() { ScriptContext::current() = ScriptContext{}; }

std::size_t StoryScript::createStories() {
    const std::size_t before = board_.stories().size();
    try {
        python_.prependPath(script_.parent_path());
        const py::module_ core = py::module_::import("_sbsim");
        const py::object boardHandle = core.attr("_board")();
        // Import by path, so the file name need not be a valid module name.
        const py::module_ util = py::module_::import("importlib.util");
        const py::object spec = util.attr("spec_from_file_location")("__story__", script_.string());
        const py::object module = util.attr("module_from_spec")(spec);
        module.attr("board") = boardHandle;  // Artery scripts use a module-level `board`
        py::module_::import("sys").attr("modules")["__story__"] = module;
        spec.attr("loader").attr("exec_module")(module);
        if (!py::hasattr(module, "createStories")) {
            throw StoryError(script_.string() + ": the script defines no createStories(board) function");
        }
        const py::object create = module.attr("createStories");
        if (parameterCount(create) == 0) {
            create();
        } else {
            create(boardHandle);
        }
    } catch (py::error_already_set& e) {
        throwStoryError(e, "while loading the story");
    }
    return board_.stories().size() - before;
}

}  // namespace sbsim::storyboard
