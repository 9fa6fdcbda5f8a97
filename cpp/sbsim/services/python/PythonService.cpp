#include "sbsim/services/python/PythonService.h"

#include <fmt/format.h>

#include <stdexcept>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/CounterRandom.h"
#include "sbsim/services/python/PythonError.h"
#include "sbsim/services/python/PythonMessage.h"

namespace py = pybind11;

namespace sbsim::services::python {

namespace {
/// The base class's methods: a class that does not define one is not called for it.
py::object baseClass() { return py::module_::import("storyboard.services").attr("Service"); }
}  // namespace

PythonService& ServiceHandle::get() const {
    if (*service == nullptr) throw std::runtime_error("this service's station has left the simulation");
    return **service;
}

PythonService::PythonService(py::object cls) : cls_(std::move(cls)), alive_(std::make_shared<PythonService*>(this)) {
    typeName_ = py::str(cls_.attr("__qualname__")).cast<std::string>();
}

PythonService::~PythonService() {
    *alive_ = nullptr;
    for (const auto& timer : timers_) {
        if (timer->isScheduled()) cancelEvent(*timer);
    }
}

py::object PythonService::method(const char* name) const {
    const py::object own = cls_.attr(name);
    if (own.is(baseClass().attr(name))) return py::none();
    return self_.attr(name);
}

template <typename... Args>
void PythonService::call(const py::object& method, const char* name, Args&&... args) {
    callAs(method, fmt::format("in {}.{}", typeName_, name), std::forward<Args>(args)...);
}

template <typename... Args>
void PythonService::callAs(const py::object& method, const std::string& during, Args&&... args) {
    try {
        method(std::forward<Args>(args)...);
    } catch (py::error_already_set& e) {
        std::string file;
        try {
            file = py::module_::import("inspect").attr("getsourcefile")(cls_).cast<std::string>();
        } catch (const std::exception&) {
            PyErr_Clear();
        }
        throw std::runtime_error(describePythonError(e, file, during));
    }
}

void PythonService::initialize() {
    try {
        self_ = cls_.attr("__new__")(cls_);
        // The handle before __init__: a constructor may ask for its attributes already.
        self_.attr("_host") = py::cast(ServiceHandle{alive_});
    } catch (py::error_already_set& e) {
        throw std::runtime_error(describePythonError(e, "", "while making " + typeName_));
    }
    call(self_.attr("__init__"), "__init__");
    initialize_ = method("initialize");
    trigger_ = method("trigger");
    signal_ = method("receive_signal");
    indicate_ = method("indicate");
    batch_ = method("indicate_batch");
    cam_ = method("on_cam");
    denm_ = method("on_denm");
    finish_ = method("finish");
    if (!batch_.is_none()) pending_ = std::make_shared<MessageBatch>(MessageStore::shared());
    batchOnly_ = pending_ && cam_.is_none() && denm_.is_none();
    if (!initialize_.is_none()) call(initialize_, "initialize");
}

void PythonService::flushBatch() {
    if (!pending_ || pending_->size() == 0) return;
    call(batch_, "indicate_batch", py::cast(pending_));
    // The same memory again unless Python kept the batch (or a column of it).
    if (pending_.use_count() == 1) {
        pending_->clear();
    } else {
        pending_ = std::make_shared<MessageBatch>(MessageStore::shared());
    }
}

void PythonService::trigger() {
    flushBatch();
    if (!trigger_.is_none()) call(trigger_, "trigger");
}

void PythonService::receiveSignal(const traffic::StoryboardSignal& signal) {
    if (!signal_.is_none())
        call(signal_, "receive_signal", py::cast(std::make_shared<traffic::StoryboardSignal>(signal)));
}

void PythonService::indicate(const radio::V2xMessage& message) {
    // The batched service's path, per reception: nothing else to prepare.
    if (batchOnly_) return pending_->add(message, simTime());
    last_ = nullptr;
    lastRecord_.reset();
    const bool handlers = !cam_.is_none() || !denm_.is_none();
    if (pending_) {
        pending_->add(message, simTime());
        if (!handlers) return;
    } else if (indicate_.is_none() && !handlers) {
        return;
    }
    auto record = std::make_shared<ReceivedMessage>(ReceivedMessage::of(message, simTime()));
    if (handlers) {
        last_ = &message;
        lastRecord_ = record;
    }
    if (!pending_ && !indicate_.is_none()) call(indicate_, "indicate", py::cast(std::move(record)));
}

void PythonService::indicateCam(const facilities::Cam& cam) {
    if (cam_.is_none()) return;
    // The middleware hands the message to indicate() first: its copy is lastRecord_.
    if (last_ != &cam || !lastRecord_ || !lastRecord_->cam)
        throw std::logic_error("a CAM reached on_cam without indicate");
    call(cam_, "on_cam", py::cast(std::shared_ptr<facilities::CamContent>(lastRecord_, &*lastRecord_->cam)));
}

void PythonService::indicateDenm(const facilities::Denm& denm) {
    if (denm_.is_none()) return;
    if (last_ != &denm || !lastRecord_ || !lastRecord_->denm)
        throw std::logic_error("a DENM reached on_denm without indicate");
    call(denm_, "on_denm", py::cast(lastRecord_->denm));
}

void PythonService::finish() {
    if (!self_) return;  // initialize() failed
    flushBatch();
    if (!finish_.is_none()) call(finish_, "finish");
}

void PythonService::sendMessage(std::string type, std::size_t bytes, py::object payload, bool camSecurity) {
    send(std::make_unique<PythonMessage>(std::move(type), bytes, std::move(payload), camSecurity));
}

std::uint64_t PythonService::scheduleCallback(kernel::SimTime delay, py::object callback) {
    if (delay < kernel::SimTime::zero()) throw std::invalid_argument("schedule_after: the delay must be >= 0 s");
    Timer* timer = nullptr;
    if (idleTimers_.empty()) {
        timers_.push_back(std::make_unique<Timer>());
        timer = timers_.back().get();
    } else {
        timer = idleTimers_.back();
        idleTimers_.pop_back();
    }
    timer->handle = nextHandle_++;
    timer->callback = std::move(callback);
    pendingTimers_.emplace(timer->handle, timer);
    scheduleAfter(delay, *timer);
    return timer->handle;
}

bool PythonService::cancelCallback(std::uint64_t handle) {
    const auto it = pendingTimers_.find(handle);
    if (it == pendingTimers_.end()) return false;
    Timer* timer = it->second;
    pendingTimers_.erase(it);
    cancelEvent(*timer);
    timer->callback = py::object();
    idleTimers_.push_back(timer);
    return true;
}

facilities::ActionId PythonService::sendDenm(const DenmRequest& request) {
    facilities::DenmContent denm;
    denm.action = denms_.requestActionId();
    denm.detectionTime = simTime();
    denm.referenceTime = denm.detectionTime;
    denm.eventPosition = request.position.value_or(position());
    denm.destination = {denm.eventPosition, request.area};
    denm.cause = request.cause;
    denm.subcause = request.subcause;
    denm.relevanceDistance = request.relevance;
    denm.validity = request.validity;
    denm.trafficClass = request.trafficClass;
    denms_.send(denm, Repetition{request.interval, request.repetition});
    return denm.action;
}

void PythonService::handleMessage(kernel::Message& msg) {
    if (denms_.handle(msg)) return;
    if (msg.kind() != Timer::kKind) return Service::handleMessage(msg);
    auto& timer = static_cast<Timer&>(msg);
    pendingTimers_.erase(timer.handle);
    const py::object callback = std::exchange(timer.callback, py::object());
    idleTimers_.push_back(&timer);  // free for the callback's own schedule_after
    std::string name = "a callback";
    if (py::hasattr(callback, "__qualname__")) name = py::str(callback.attr("__qualname__")).cast<std::string>();
    callAs(callback, "in " + name + ", scheduled with schedule_after");
}

kernel::SimTime PythonService::startPhase(kernel::SimTime interval) const {
    radio::CounterRandom random(simulation().seed(), radio::CounterRandom::keyOf(stationId()), 0, 0,
                                radio::DrawPurpose::Start);
    return kernel::SimTime::fromNanoseconds(
        static_cast<kernel::SimTime::rep>(random.uniform01() * static_cast<double>(interval.raw())));
}

}  // namespace sbsim::services::python
