#include "sbsim/services/python/PythonError.h"

#include <cstdio>

#include "sbsim/kernel/OneLine.h"

namespace py = pybind11;

namespace sbsim::services::python {

std::string describePythonError(py::error_already_set& error, const std::string& file, const std::string& during) {
    std::string where = file;
    try {
        std::string details;
        const py::object lines =
            py::module_::import("traceback").attr("format_exception")(error.type(), error.value(), error.trace());
        for (const py::handle line : lines) details += line.cast<std::string>();
        std::fputs(details.c_str(), stderr);
        if (error.matches(PyExc_SyntaxError)) {
            const py::object value = error.value();
            const py::object f = value.attr("filename");
            const py::object l = value.attr("lineno");
            where = f.is_none() ? file : py::str(f).cast<std::string>();
            if (!l.is_none()) where += ":" + py::str(l).cast<std::string>();
        } else {
            std::string innermost, inFile;
            for (py::object tb = error.trace(); tb && !tb.is_none(); tb = tb.attr("tb_next")) {
                const std::string name = tb.attr("tb_frame").attr("f_code").attr("co_filename").cast<std::string>();
                innermost = name + ":" + py::str(tb.attr("tb_lineno")).cast<std::string>();
                if (name == file) inFile = innermost;
            }
            if (!inFile.empty()) {
                where = inFile;
            } else if (!innermost.empty()) {
                where = innermost;
            }
        }
    } catch (const std::exception&) {
        PyErr_Clear();  // formatting failed: the class's file must do
    }
    const std::string type = error.type() ? py::str(error.type().attr("__name__")).cast<std::string>() : "Error";
    const std::string message = kernel::oneLine(py::str(error.value()).cast<std::string>());
    return where + ": " + type + ": " + message + " (" + during + ")";
}

}  // namespace sbsim::services::python
