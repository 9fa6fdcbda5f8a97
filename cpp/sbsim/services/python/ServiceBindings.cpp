// The `_sbsim_services` module: what a Python service's storyboard.services.Service base class asks
// and commands through (Host), and the objects its callbacks receive. Thin: each call is the C++
// service's (PythonService, Service, ServiceVehicle); the Python base class names them.

#include <pybind11/embed.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <variant>

#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/services/python/MessageBatch.h"
#include "sbsim/services/python/PythonService.h"
#include "sbsim/services/python/ReceivedMessage.h"
#include "sbsim/traffic/StoryboardSignal.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace py = pybind11;

namespace sbsim::services::python {

namespace {

using kernel::SimTime;

using Host = ServiceHandle;

/// A delay or interval in seconds, as the services file's durations: finite and >= 0.
SimTime seconds(double s, const char* what) {
    if (!std::isfinite(s) || s < 0 || s > ServiceSpec::kMaxDurationSeconds) {
        throw py::value_error(std::string(what) + ": seconds must be a finite number from 0 to 1e9");
    }
    return SimTime::fromSeconds(s);
}

/// The running vehicle's row in the snapshot; a roadside unit or a vehicle not in it has none.
std::optional<traffic::VehicleSnapshot::Index> row(const PythonService& s) {
    return s.roadsideUnit() ? std::nullopt : s.selfIndex();
}

/// The station's own vehicle, for commands and SUMO's answers; refused on a roadside unit.
ServiceVehicle& vehicleOf(PythonService& s) {
    if (s.roadsideUnit()) throw std::runtime_error("a roadside unit has no vehicle to ask or command");
    return s.vehicle();
}

template <typename T>
py::object orNone(const std::optional<T>& v) {
    return v ? py::cast(*v) : py::none();
}

/// The step's snapshot columns for all Python services: a read-only numpy view of the snapshot's
/// own array (no copy), the same view for every read in the step. The view holds the array
/// (traffic::SharedColumn), so one kept past its step stays valid and keeps that step's values:
/// the next refill writes into a spare array while it is held.
struct StepArrays {
    const traffic::VehicleSnapshot* snapshot = nullptr;
    SimTime time = SimTime::max();
    std::size_t size = std::numeric_limits<std::size_t>::max();
    py::dict columns;  // this step's views, by name

    void renew(const traffic::VehicleSnapshot& s) {
        if (snapshot == &s && time == s.time() && size == static_cast<std::size_t>(s.size())) return;
        snapshot = &s;
        time = s.time();
        size = static_cast<std::size_t>(s.size());
        columns = py::dict();  // the last step's views: freed unless a service kept them
    }
    template <typename Array>
    py::object column(const char* name, std::shared_ptr<const Array> array, py::ssize_t width) {
        if (columns.contains(name)) return columns[name];
        using Held = std::shared_ptr<const Array>;
        const double* data = array->data();
        const auto rows = static_cast<py::ssize_t>(array->size()) / width;
        const py::capsule base(new Held(std::move(array)), [](void* p) { delete static_cast<Held*>(p); });
        py::array out = width == 1 ? py::array(py::dtype::of<double>(), {rows}, {}, data, base)
                                   : py::array(py::dtype::of<double>(), {rows, width}, {}, data, base);
        out.attr("setflags")(py::arg("write") = false);
        columns[name] = out;
        return out;
    }
};

StepArrays& stepArrays() {
    // Kept in the module (freed with the interpreter), not as a C++ static holding Python objects.
    static StepArrays* arrays = nullptr;
    if (arrays == nullptr) {
        py::object holder = py::cast(StepArrays{}, py::return_value_policy::move);
        py::module_::import("_sbsim_services").attr("_step_arrays") = holder;
        arrays = &holder.cast<StepArrays&>();
    }
    return *arrays;
}

/// A view of a batch's column: its memory, kept alive by the batch.
py::array columnView(const std::shared_ptr<MessageBatch>& batch, const std::vector<double>& column, py::ssize_t width) {
    const py::object base = py::cast(batch);
    const auto rows = static_cast<py::ssize_t>(column.size()) / width;
    py::array out = width == 1 ? py::array(py::dtype::of<double>(), {rows}, {}, column.data(), base)
                               : py::array(py::dtype::of<double>(), {rows, width}, {}, column.data(), base);
    out.attr("setflags")(py::arg("write") = false);
    return out;
}

/// A batch column's property: the column as a numpy view that keeps the batch alive (`width` values a message).
auto batchColumn(MessageBatch::Column c, py::ssize_t width) {
    return [c, width](const std::shared_ptr<MessageBatch>& b) { return columnView(b, b->column(c), width); };
}

py::tuple xy(const Eigen::Vector2d& p) { return py::make_tuple(p.x(), p.y()); }

/// "station:sequence" (Denm.action, send_denm's answer) as an action id.
facilities::ActionId actionOf(const std::string& text) {
    const std::size_t colon = text.rfind(':');
    const std::string digits = colon == std::string::npos ? std::string() : text.substr(colon + 1);
    if (colon == 0 || digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos) {
        throw py::value_error("terminate_denm: '" + text + "' is not an action id ('station:sequence')");
    }
    return {text.substr(0, colon), static_cast<std::uint32_t>(std::stoul(digits))};
}

py::object studyValue(const std::optional<kernel::StudyParameters::Value>& v) {
    if (!v) return py::none();
    return std::visit([](const auto& x) -> py::object { return py::cast(x); }, *v);
}

std::shared_ptr<facilities::CamContent> camOf(const std::shared_ptr<ReceivedMessage>& m) {
    return m->cam ? std::shared_ptr<facilities::CamContent>(m, &*m->cam) : nullptr;
}
std::shared_ptr<facilities::DenmContent> denmOf(const std::shared_ptr<ReceivedMessage>& m) { return m->denm; }

void bindMessages(py::module_& m) {
    py::class_<facilities::CamContent, std::shared_ptr<facilities::CamContent>>(m, "Cam")
        .def_property_readonly("station", [](const facilities::CamContent& c) { return c.station; })
        .def_property_readonly("generation_time",
                               [](const facilities::CamContent& c) { return c.generationTime.seconds(); })
        .def_property_readonly("position", [](const facilities::CamContent& c) { return xy(c.position); })
        .def_property_readonly("speed", [](const facilities::CamContent& c) { return c.speed; })
        .def_property_readonly("heading", [](const facilities::CamContent& c) { return c.heading; })
        .def_property_readonly("acceleration", [](const facilities::CamContent& c) { return c.acceleration; })
        .def_property_readonly("length", [](const facilities::CamContent& c) { return c.length; })
        .def_property_readonly("width", [](const facilities::CamContent& c) { return c.width; })
        .def_property_readonly("yaw_rate", [](const facilities::CamContent& c) { return c.yawRate; })
        .def_property_readonly(
            "roadside_unit",
            [](const facilities::CamContent& c) { return c.stationType == facilities::StationType::RoadSideUnit; })
        .def("__repr__", [](const facilities::CamContent& c) { return "<Cam from " + c.station + ">"; });

    py::class_<facilities::DenmContent, std::shared_ptr<facilities::DenmContent>>(m, "Denm")
        .def_property_readonly("action", [](const facilities::DenmContent& d) { return d.action.str(); })
        .def_property_readonly("station", [](const facilities::DenmContent& d) { return d.action.station; })
        .def_property_readonly("cause", [](const facilities::DenmContent& d) { return d.cause; })
        .def_property_readonly("subcause", [](const facilities::DenmContent& d) { return d.subcause; })
        .def_property_readonly("event_position", [](const facilities::DenmContent& d) { return xy(d.eventPosition); })
        .def_property_readonly("detection_time",
                               [](const facilities::DenmContent& d) { return d.detectionTime.seconds(); })
        .def_property_readonly("reference_time",
                               [](const facilities::DenmContent& d) { return d.referenceTime.seconds(); })
        .def_property_readonly("expiry", [](const facilities::DenmContent& d) { return d.expiry().seconds(); })
        .def_property_readonly("terminated", [](const facilities::DenmContent& d) { return d.termination.has_value(); })
        .def("__repr__", [](const facilities::DenmContent& d) { return "<Denm " + d.action.str() + ">"; });

    py::class_<ReceivedMessage, std::shared_ptr<ReceivedMessage>>(m, "Message")
        .def_property_readonly("type", [](const ReceivedMessage& r) { return r.type; })
        .def_property_readonly("sender", [](const ReceivedMessage& r) { return r.sender; })
        .def_property_readonly("sent_at", [](const ReceivedMessage& r) { return r.sentAt.seconds(); })
        .def_property_readonly("received_at", [](const ReceivedMessage& r) { return r.receivedAt.seconds(); })
        .def_property_readonly("sequence", [](const ReceivedMessage& r) { return r.sequence; })
        .def_property_readonly("size", [](const ReceivedMessage& r) { return r.size; })
        .def_property_readonly("frame_bytes", [](const ReceivedMessage& r) { return r.frameBytes; })
        .def_property_readonly("payload", [](const ReceivedMessage& r) { return r.payload; })
        .def_property_readonly("cam", [](const std::shared_ptr<ReceivedMessage>& r) { return camOf(r); })
        .def_property_readonly("denm", [](const std::shared_ptr<ReceivedMessage>& r) { return denmOf(r); })
        .def("__repr__", [](const ReceivedMessage& r) { return "<Message " + r.type + " from " + r.sender + ">"; });

    py::class_<MessageBatch, std::shared_ptr<MessageBatch>>(m, "Messages")
        .def("__len__", &MessageBatch::size)
        .def("__getitem__",
             [](const MessageBatch& b, py::ssize_t i) {
                 const auto n = static_cast<py::ssize_t>(b.size());
                 if (i < 0) i += n;
                 if (i < 0 || i >= n) throw py::index_error("message index out of range");
                 return std::make_shared<ReceivedMessage>(b.at(static_cast<std::size_t>(i)));
             })
        .def_property_readonly("types", &MessageBatch::types)
        .def_property_readonly("senders", &MessageBatch::senders)
        .def_property_readonly("received_at", batchColumn(MessageBatch::Column::ReceivedAt, 1))
        .def_property_readonly("sent_at", batchColumn(MessageBatch::Column::SentAt, 1))
        .def_property_readonly("sizes", batchColumn(MessageBatch::Column::Size, 1))
        .def_property_readonly("cam_positions", batchColumn(MessageBatch::Column::CamPosition, 2))
        .def_property_readonly("cam_speeds", batchColumn(MessageBatch::Column::CamSpeed, 1))
        .def_property_readonly("cam_headings", batchColumn(MessageBatch::Column::CamHeading, 1));

    py::class_<traffic::StoryboardSignal, std::shared_ptr<traffic::StoryboardSignal>>(m, "Signal")
        .def_property_readonly("cause", [](const traffic::StoryboardSignal& s) { return s.cause; })
        .def_property_readonly("story", [](const traffic::StoryboardSignal& s) { return s.story; })
        .def_property_readonly("ego", [](const traffic::StoryboardSignal& s) { return s.ego; })
        .def_property_readonly("others", [](const traffic::StoryboardSignal& s) { return s.others; })
        .def_property_readonly("on_exit", [](const traffic::StoryboardSignal& s) { return s.onExit; })
        .def("__repr__", [](const traffic::StoryboardSignal& s) { return "<Signal " + s.cause + ">"; });

    py::class_<StepArrays>(m, "_StepArrays");
}

void bindHost(py::module_& m) {
    using Snap = traffic::VehicleSnapshot;
    py::class_<Host>(m, "Host")
        .def("station_id", [](const Host& h) { return h.get().stationId(); })
        .def("roadside_unit", [](const Host& h) { return h.get().roadsideUnit(); })
        .def("time", [](const Host& h) { return h.get().simTime().seconds(); })
        .def("parameter", [](const Host& h, const std::string& name) { return h.get().parameter(name); })
        .def("study_parameter",
             [](const Host& h, const std::string& name) { return studyValue(h.get().studyParameter(name)); })
        .def("position", [](const Host& h) { return xy(h.get().position()); })
        .def("self_index", [](const Host& h) { return orNone(row(h.get())); })
        .def("speed",
             [](const Host& h) -> py::object {
                 const auto i = row(h.get());
                 return i ? py::cast(h.get().snapshot().speeds()[*i]) : py::none();
             })
        .def("heading",
             [](const Host& h) -> py::object {
                 const auto i = row(h.get());
                 return i ? py::cast(h.get().snapshot().angles()[*i]) : py::none();
             })
        .def("acceleration",
             [](const Host& h) -> py::object {
                 const auto i = row(h.get());
                 return i ? py::cast(h.get().snapshot().accelerations()[*i]) : py::none();
             })
        .def("edge", [](const Host& h) { return vehicleOf(h.get()).roadId(); })
        .def("lane", [](const Host& h) { return vehicleOf(h.get()).laneId(); })
        .def("lane_index", [](const Host& h) { return vehicleOf(h.get()).laneIndex(); })
        .def("driving_distance",
             [](const Host& h, double x, double y) { return vehicleOf(h.get()).drivingDistanceTo(x, y); })
        .def("driving_distance_to_edge", [](const Host& h, const std::string& edge,
                                            double pos) { return vehicleOf(h.get()).drivingDistance(edge, pos); })
        .def(
            "snapshot_ids", [](const Host& h) -> const std::vector<std::string>& { return h.get().snapshot().ids(); },
            py::return_value_policy::copy)
        .def("snapshot_size", [](const Host& h) { return h.get().snapshot().size(); })
        .def("snapshot_index_of",
             [](const Host& h, const std::string& id) { return orNone(h.get().snapshot().indexOf(id)); })
        .def("snapshot_time", [](const Host& h) { return h.get().snapshot().time().seconds(); })
        .def("snapshot_column",
             [](const Host& h, const std::string& name) -> py::object {
                 const Snap& s = h.get().snapshot();
                 StepArrays& arrays = stepArrays();
                 arrays.renew(s);
                 // Eigen keeps positions column-major 2 x N: one vehicle's x, y adjacent.
                 if (name == "positions") return arrays.column("positions", s.sharedPositions(), 2);
                 if (name == "speeds") return arrays.column("speeds", s.sharedSpeeds(), 1);
                 if (name == "angles") return arrays.column("angles", s.sharedAngles(), 1);
                 if (name == "accelerations") return arrays.column("accelerations", s.sharedAccelerations(), 1);
                 if (name == "lengths") return arrays.column("lengths", s.sharedLengths(), 1);
                 if (name == "widths") return arrays.column("widths", s.sharedWidths(), 1);
                 throw py::value_error("no snapshot column '" + name + "'");
             })
        // For tests: where the snapshot keeps a column now, to show a view points at it (no copy).
        .def("_snapshot_column_address",
             [](const Host& h, const std::string& name) -> std::uintptr_t {
                 const Snap& s = h.get().snapshot();
                 if (name == "positions") return reinterpret_cast<std::uintptr_t>(s.positions().data());
                 if (name == "speeds") return reinterpret_cast<std::uintptr_t>(s.speeds().data());
                 if (name == "angles") return reinterpret_cast<std::uintptr_t>(s.angles().data());
                 if (name == "accelerations") return reinterpret_cast<std::uintptr_t>(s.accelerations().data());
                 if (name == "lengths") return reinterpret_cast<std::uintptr_t>(s.lengths().data());
                 if (name == "widths") return reinterpret_cast<std::uintptr_t>(s.widths().data());
                 throw py::value_error("no snapshot column '" + name + "'");
             })
        .def("ldm",
             [](const Host& h) {
                 py::dict out;
                 for (const auto& [station, entry] : h.get().localDynamicMap().entries())
                     out[py::str(station)] = std::make_shared<facilities::CamContent>(entry.cam);
                 return out;
             })
        .def("denms",
             [](const Host& h) {
                 std::vector<std::shared_ptr<facilities::DenmContent>> out;
                 for (const auto& [action, entry] : h.get().denmMemory().entries())
                     out.push_back(std::make_shared<facilities::DenmContent>(entry.denm));
                 return out;
             })
        .def("channel_busy_ratio", [](const Host& h) { return h.get().medium().channelBusyRatio(h.get().stationId()); })
        .def("dcc_interval",
             [](const Host& h) -> py::object {
                 const auto interval = h.get().medium().dccInterval(h.get().stationId());
                 return interval ? py::cast(interval->seconds()) : py::none();
             })
        .def("send",
             [](const Host& h, std::string type, std::size_t bytes, py::object payload, bool camSecurity) {
                 h.get().sendMessage(std::move(type), bytes, std::move(payload), camSecurity);
             })
        .def(
            "send_denm",
            [](const Host& h, int cause, int subcause, double area, double validity, double interval, double repetition,
               std::optional<std::pair<double, double>> position, std::optional<double> relevance, int trafficClass) {
                PythonService::DenmRequest r{.cause = cause,
                                             .subcause = subcause,
                                             .area = area,
                                             .validity = seconds(validity, "send_denm validity"),
                                             .interval = seconds(interval, "send_denm interval"),
                                             .repetition = seconds(repetition, "send_denm repetition"),
                                             .position = std::nullopt,
                                             .relevance = relevance,
                                             .trafficClass = trafficClass};
                if (position) r.position = Eigen::Vector2d(position->first, position->second);
                return h.get().sendDenm(r).str();
            })
        .def("terminate_denm",
             [](const Host& h, const std::string& action) { return h.get().terminateDenm(actionOf(action)); })
        .def("schedule_after",
             [](const Host& h, double delay, py::object callback) {
                 return h.get().scheduleCallback(seconds(delay, "schedule_after"), std::move(callback));
             })
        .def("cancel", [](const Host& h, std::uint64_t handle) { return h.get().cancelCallback(handle); })
        .def("start_phase",
             [](const Host& h, double interval) {
                 return h.get().startPhase(seconds(interval, "start_phase")).seconds();
             })
        .def("listen_to_all_signals", [](const Host& h) { h.get().listenToAllSignals(); })
        .def("record_scalar", [](const Host& h, const std::string& name, double v) { h.get().recordScalar(name, v); })
        .def("emit", [](const Host& h, const std::string& name, double v) { h.get().emit(name, v); })
        .def("set_max_speed", [](const Host& h, double v) { vehicleOf(h.get()).setMaxSpeed(v); })
        .def("end_max_speed", [](const Host& h) { vehicleOf(h.get()).endMaxSpeed(); })
        .def("stop", [](const Host& h) { vehicleOf(h.get()).stop(); })
        .def("end_stop", [](const Host& h) { vehicleOf(h.get()).endStop(); })
        .def("change_lane", [](const Host& h, int index,
                               double s) { vehicleOf(h.get()).changeLane(index, seconds(s, "change_lane").seconds()); })
        .def("change_lane_relative",
             [](const Host& h, int offset, double s) {
                 vehicleOf(h.get()).changeLaneRelative(offset, seconds(s, "change_lane_relative").seconds());
             })
        .def("set_speed_factor", [](const Host& h, double f) { vehicleOf(h.get()).holdSpeedFactor(f); })
        .def("end_speed_factor", [](const Host& h) { vehicleOf(h.get()).endSpeedFactor(); })
        .def("set_color",
             [](const Host& h, int r, int g, int b, int a) {
                 for (const int c : {r, g, b, a}) {
                     if (c < 0 || c > 255) throw py::value_error("set_color: each channel must be from 0 to 255");
                 }
                 vehicleOf(h.get()).holdColor({static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g),
                                               static_cast<std::uint8_t>(b), static_cast<std::uint8_t>(a)});
             })
        .def("end_color", [](const Host& h) { vehicleOf(h.get()).endColor(); })
        .def("change_target", [](const Host& h, const std::string& edge) { vehicleOf(h.get()).changeTarget(edge); })
        .def("end_route", [](const Host& h) { vehicleOf(h.get()).endRoute(); });
}

}  // namespace

PYBIND11_EMBEDDED_MODULE(_sbsim_services, m) {
    m.doc() = "sbsim's host side of Python services (storyboard.services).";
    bindMessages(m);
    bindHost(m);
}

}  // namespace sbsim::services::python
