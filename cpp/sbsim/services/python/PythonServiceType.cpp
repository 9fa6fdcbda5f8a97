// The services file's `python:` types: one resolver in the service registry imports the named
// class (once per file and class), checks it (storyboard.services._check: a subclass of Service,
// methods taking what sbsim passes, the services file's attributes declared) and makes a
// PythonService around it per station.

#include "sbsim/services/python/PythonServiceType.h"

#include <pybind11/embed.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/python/PythonError.h"
#include "sbsim/services/python/PythonService.h"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace sbsim::services::python {

namespace {

[[noreturn]] void refuse(const ServiceSpec& spec, const std::string& message) {
    throw ServicesConfigError(fmt::format("{}:{}: service '{}': {}", spec.source, spec.line, spec.type, message));
}

/// "python:warner.py:Warner" as (warner.py, Warner).
std::pair<std::string, std::string> target(const ServiceSpec& spec) {
    const std::string rest = spec.type.substr(std::string_view(kPythonPrefix).size());
    const std::size_t colon = rest.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == rest.size()) {
        refuse(spec, "a Python service is named 'python:FILE.py:Class' or 'python:package.module:Class'");
    }
    return {rest.substr(0, colon), rest.substr(colon + 1)};
}

bool isFile(const std::string& where) { return where.size() > 3 && where.compare(where.size() - 3, 3, ".py") == 0; }

/// The module `where` names: a file (relative to the services file) or a module name.
py::object importModule(const ServiceSpec& spec, const std::string& where) {
    const fs::path dir = fs::absolute(fs::path(spec.source)).parent_path();
    const py::module_ sys = py::module_::import("sys");
    if (!isFile(where)) {
        py::list path = sys.attr("path");
        if (!path.contains(py::str(dir.string()))) path.append(dir.string());  // after the story's folder
        try {
            return py::module_::import("importlib").attr("import_module")(where);
        } catch (py::error_already_set& e) {
            if (e.matches(PyExc_ModuleNotFoundError)) {
                const std::string message = py::str(e.value()).cast<std::string>();
                PyErr_Clear();
                refuse(spec, fmt::format("cannot import module '{}': {}", where, message));
            }
            refuse(spec, describePythonError(e, "", "while importing " + where));
        }
    }
    const fs::path file = (dir / where).lexically_normal();
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) refuse(spec, fmt::format("no such file '{}'", file.string()));
    const std::string name = "sbsim_service:" + file.string();
    const py::dict modules = sys.attr("modules");
    if (modules.contains(name)) return modules[py::str(name)];
    try {
        const py::module_ util = py::module_::import("importlib.util");
        const py::object moduleSpec = util.attr("spec_from_file_location")(name, file.string());
        const py::object module = util.attr("module_from_spec")(moduleSpec);
        modules[py::str(name)] = module;
        try {
            moduleSpec.attr("loader").attr("exec_module")(module);
        } catch (...) {
            modules.attr("pop")(name, py::none());
            throw;
        }
        return module;
    } catch (py::error_already_set& e) {
        refuse(spec, describePythonError(e, file.string(), "while importing " + file.string()));
    }
}

/// The class `spec` names, imported and checked once per services file and type.
py::object serviceClass(const ServiceSpec& spec) {
    if (!Py_IsInitialized()) refuse(spec, "Python services need sbsim's embedded interpreter");
    const py::module_ core = py::module_::import("_sbsim_services");
    if (!py::hasattr(core, "_classes")) core.attr("_classes") = py::dict();
    const py::dict classes = core.attr("_classes");
    const py::tuple key = py::make_tuple(fs::absolute(spec.source).string(), spec.type);
    if (classes.contains(key)) return classes[key];
    const auto [where, name] = target(spec);
    const py::object module = importModule(spec, where);
    if (!py::hasattr(module, name.c_str())) {
        refuse(spec,
               fmt::format("{} defines no class '{}'", isFile(where) ? "'" + where + "'" : "module " + where, name));
    }
    const py::object cls = module.attr(name.c_str());
    try {
        py::dict attributes;
        for (const auto& [key, value] : spec.parameters) attributes[py::str(key)] = py::str(value);
        const py::object problem = py::module_::import("storyboard.services").attr("_check")(cls, attributes);
        if (!problem.is_none()) refuse(spec, problem.cast<std::string>());
    } catch (py::error_already_set& e) {
        refuse(spec, describePythonError(e, "", "while checking " + name));
    }
    classes[key] = cls;
    return cls;
}

/// What the class declares it provides: `sends_denms = True` (checked a bool by storyboard.services._check).
ServiceTraits traitsOf(const ServiceSpec& spec) {
    const py::object cls = serviceClass(spec);
    return {.sendsDenms = py::getattr(cls, "sends_denms", py::bool_(false)).cast<bool>()};
}

/// A file-named class's file; a module-named class's once it is imported (the run's services are
/// made): its module's file, and the file of the module that defines the class if that is another.
std::vector<fs::path> filesOf(const ServiceSpec& spec) {
    const auto [where, name] = target(spec);
    if (isFile(where)) return {(fs::absolute(fs::path(spec.source)).parent_path() / where).lexically_normal()};
    if (!Py_IsInitialized()) return {};
    const py::module_ core = py::module_::import("_sbsim_services");
    if (!py::hasattr(core, "_classes")) return {};
    const py::dict classes = core.attr("_classes");
    const py::tuple key = py::make_tuple(fs::absolute(spec.source).string(), spec.type);
    if (!classes.contains(key)) return {};
    const py::object cls = classes[key];
    const py::dict modules = py::module_::import("sys").attr("modules");
    std::vector<fs::path> out;
    for (const py::object& module : {modules.attr("get")(where), modules.attr("get")(cls.attr("__module__"))}) {
        const py::object file = py::getattr(module, "__file__", py::none());
        if (!py::isinstance<py::str>(file)) continue;  // a namespace package, a built-in module
        const fs::path path = fs::absolute(fs::path(file.cast<std::string>())).lexically_normal();
        if (std::find(out.begin(), out.end(), path) == out.end()) out.push_back(path);
    }
    return out;
}

// Registered when libsbsim loads, as the bundled services are.
struct Registration {
    Registration() {
        ServiceRegistry::instance().addResolver(kPythonPrefix,
                                                {.check = [](const ServiceSpec& spec) { (void)serviceClass(spec); },
                                                 .create = [](const ServiceSpec& spec) -> std::unique_ptr<Service> {
                                                     return std::make_unique<PythonService>(serviceClass(spec));
                                                 },
                                                 .traits = traitsOf,
                                                 .files = filesOf});
    }
};
const Registration kRegistration;

}  // namespace

bool usesPython(const ServicesConfig& config) {
    const auto python = [](const ServiceSpec& s) { return s.type.rfind(kPythonPrefix, 0) == 0; };
    for (const ServiceSpec& s : config.services()) {
        if (python(s)) return true;
    }
    for (const RoadsideUnitSpec& rsu : config.roadsideUnits()) {
        for (const ServiceSpec& s : rsu.services) {
            if (python(s)) return true;
        }
    }
    return false;
}

}  // namespace sbsim::services::python
