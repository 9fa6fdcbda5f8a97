#include "storyboard/python/ScriptContext.h"

#include "storyboard/StoryError.h"

namespace py = pybind11;

namespace sbsim::storyboard {

ScriptContext& ScriptContext::current() {
    static ScriptContext context;
    return context;
}

namespace {

std::string oneLine(const std::string& text) {
    std::string out;
    bool space = false;
    for (const char c : text) {
        if (c == '\n' || c == '\r' || c == '\t' || c == ' ') {
            space = !out.empty();
            continue;
        }
        if (space) out.push_back(' ');
        space = false;
        out.push_back(c);
    }
    return out;
}

}  // namespace

void throwStoryError(py::error_already_set& error, const std::string& during) {
    const std::string script = ScriptContext::current().script.string();
    std::string details;
    std::string where;
    try {
        const py::object lines =
            py::module_::import("traceback").attr("format_exception")(error.type(), error.value(), error.trace());
        for (const py::handle line : lines) details += line.cast<std::string>();

        if (error.matches(PyExc_SyntaxError)) {
            const py::object value = error.value();
            where = py::str(value.attr("filename")).cast<std::string>() + ":" +
                    py::str(value.attr("lineno")).cast<std::string>();
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
    const std::string message = oneLine(py::str(error.value()).cast<std::string>());
    error.restore();
    PyErr_Clear();
    throw StoryError(where + ": " + type + ": " + message + " (" + during + ")", details);
}

}  // namespace sbsim::storyboard
