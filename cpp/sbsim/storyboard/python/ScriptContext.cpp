#include "sbsim/storyboard/python/ScriptContext.h"

#include "sbsim/kernel/OneLine.h"
#include "sbsim/storyboard/StoryError.h"

namespace py = pybind11;

namespace sbsim::storyboard {

ScriptContext& ScriptContext::current() {
    static ScriptContext context;
    return context;
}

void throwStoryError(py::error_already_set& error, const std::string& during) {
    const std::string script = ScriptContext::current().script.string();
    std::string details;
    std::string where;
    try {
        const py::object lines =
            py::module_::import("traceback").attr("format_exception")(error.type(), error.value(), error.trace());
        for (const py::handle line : lines) details += line.cast<std::string>();

        if (error.matches(PyExc_SyntaxError)) {
            // A file Python cannot even compile (null bytes, a bad encoding) has no filename or
            // line in the error: then it is the script, as a whole.
            const py::object value = error.value();
            const py::object file = value.attr("filename");
            const py::object line = value.attr("lineno");
            where = file.is_none() ? script : py::str(file).cast<std::string>();
            if (!line.is_none()) where += ":" + py::str(line).cast<std::string>();
        } else {
            std::string innermost;
            for (py::object tb = error.trace(); !tb.is_none(); tb = tb.attr("tb_next")) {
                const std::string file = tb.attr("tb_frame").attr("f_code").attr("co_filename").cast<std::string>();
                const std::string here = file + ":" + py::str(tb.attr("tb_lineno")).cast<std::string>();
                innermost = here;
                if (file == script) where = here;
            }
            if (where.empty()) where = innermost.empty() ? script : innermost;
        }
    } catch (const std::exception&) {
        where = script;  // formatting failed: still name the script
    }
    const std::string type = error.type() ? py::str(error.type().attr("__name__")).cast<std::string>() : "Error";
    const std::string message = kernel::oneLine(py::str(error.value()).cast<std::string>());
    error.restore();
    PyErr_Clear();
    throw StoryError(where + ": " + type + ": " + message + " (" + during + ")", details);
}

void throwContractError(const py::handle& object, const std::string& message) {
    std::string where = ScriptContext::current().script.string();
    try {
        const py::module_ inspect = py::module_::import("inspect");
        const py::object cls = py::type::of(object);
        const py::object file = inspect.attr("getsourcefile")(cls);
        const py::tuple lines = inspect.attr("getsourcelines")(cls);
        if (!file.is_none()) where = file.cast<std::string>() + ":" + py::str(lines[1]).cast<std::string>();
    } catch (const std::exception&) {
        PyErr_Clear();  // no source to point at: the script's name must do
    }
    throw StoryError(where + ": " + kernel::oneLine(message));
}

}  // namespace sbsim::storyboard
