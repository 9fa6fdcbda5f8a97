#include "sbsim/python/StatisticsParquet.h"

#include <pybind11/embed.h>

#include <nlohmann/json.hpp>

namespace py = pybind11;

namespace sbsim::python {

namespace {

// pyarrow runs in a child Python, not in this process: SUMO's wheel loads its own libarrow and
// libparquet (another version), whose symbols pyarrow's extension modules would bind to here and
// crash. The child reads the columns as JSON on stdin and writes the Parquet file to stdout.
constexpr const char* kCheck = "import pyarrow.parquet";
constexpr const char* kWrite = R"(
import json, sys
import pyarrow as pa, pyarrow.parquet as pq
c = json.load(sys.stdin)
t = pa.table({k: pa.array(c[k], type=pa.string()) for k in ("vehicle", "source", "name")}
             | {k: pa.array(c[k], type=pa.float64()) for k in ("time", "value")}
             | {"equipped": pa.array(c["equipped"], type=pa.bool_())})
sink = pa.BufferOutputStream()
pq.write_table(t, sink)
sys.stdout.buffer.write(sink.getvalue().to_pybytes())
)";

/// Runs `code` in a child of the interpreter sbsim embeds (sys.executable), `input` on its stdin;
/// returns its stdout, or throws Unavailable with the last line it wrote on stderr.
std::string runChild(const char* code, const std::string& input) {
    const py::module_ subprocess = py::module_::import("subprocess");
    const py::object executable = py::module_::import("sys").attr("executable");
    const py::object done =
        subprocess.attr("run")(py::make_tuple(executable, "-c", code), py::arg("input") = py::bytes(input),
                               py::arg("capture_output") = true, py::arg("check") = false);
    if (done.attr("returncode").cast<int>() != 0) {
        std::string err = done.attr("stderr").cast<std::string>();
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        // The exact command for this interpreter (./sbsim installs pyarrow with the study extras).
        const std::string python = py::module_::import("shlex").attr("quote")(executable).cast<std::string>();
        throw StatisticsParquet::Unavailable("pyarrow cannot write Parquet (install it with: " + python +
                                             " -m pip install 'pyarrow>=14'): " + err.substr(err.rfind('\n') + 1));
    }
    return done.attr("stdout").cast<std::string>();
}

}  // namespace

StatisticsParquet::StatisticsParquet() { (void)runChild(kCheck, ""); }

std::string StatisticsParquet::bytes(const kernel::Statistics& s, const Equipped& equipped) const {
    nlohmann::json marks = nlohmann::json::array();
    for (const std::string& vehicle : s.vehicles()) {
        const std::optional<bool> mark = vehicle.empty() ? std::nullopt : equipped(vehicle);
        marks.push_back(mark ? nlohmann::json(*mark) : nlohmann::json(nullptr));
    }
    const nlohmann::json columns = {{"vehicle", s.vehicles()}, {"source", s.sources()}, {"name", s.names()},
                                    {"time", s.times()},       {"value", s.values()},   {"equipped", std::move(marks)}};
    return runChild(kWrite, columns.dump());
}

}  // namespace sbsim::python
