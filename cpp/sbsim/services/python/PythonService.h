#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "sbsim/facilities/ItsMessageHandler.h"
#include "sbsim/kernel/Message.h"
#include "sbsim/services/Service.h"
#include "sbsim/services/den/DenmSender.h"
#include "sbsim/services/python/MessageBatch.h"
#include "sbsim/services/python/ReceivedMessage.h"

namespace sbsim::services::python {

class PythonService;

/// The Python side's handle on its service (Service._host): it reads null once the station left,
/// so a service object kept past its station raises instead of reaching a freed one.
struct ServiceHandle {
    std::shared_ptr<PythonService*> service;
    PythonService& get() const;
};

/// A service written in Python (`<service type="python:warner.py:Warner"/>`): a C++ service like any
/// other, hosted by the station's middleware, that forwards each call to an instance of the named
/// class (derived from storyboard.services.Service). Calls go only to the methods the class
/// defines. The Python side asks and commands through this object (ServiceBindings.cpp), so the
/// semantics stay the C++ service's: the same middleware clock, facilities, effect stack and
/// statistics. A Python exception ends the run as the service's error (Service::failed), naming
/// the Python file and line.
class PythonService : public Service, public facilities::ItsMessageHandler {
public:
    /// `cls` is the class the services file names (checked by PythonServiceType).
    explicit PythonService(pybind11::object cls);
    ~PythonService() override;

    void initialize() override;
    void trigger() override;
    void receiveSignal(const traffic::StoryboardSignal& signal) override;
    void indicate(const radio::V2xMessage& message) override;
    void indicateCam(const facilities::Cam& cam) override;
    void indicateDenm(const facilities::Denm& denm) override;
    void handleMessage(kernel::Message& msg) override;
    void finish() override;

    /// The Python side's calls (ServiceBindings.cpp); the protected C++ API, made reachable.
    using Service::denmMemory;
    using Service::emit;
    using Service::facilities;
    using Service::listenToAllSignals;
    using Service::localDynamicMap;
    using Service::medium;
    using Service::parameter;
    using Service::position;
    using Service::recordScalar;
    using Service::roadsideUnit;
    using Service::selfIndex;
    using Service::snapshot;
    using Service::studyParameter;
    using Service::vehicle;
    void sendMessage(std::string type, std::size_t bytes, pybind11::object payload, bool camSecurity);
    /// Calls `callback()` after `delay`; the handle cancels it.
    std::uint64_t scheduleCallback(kernel::SimTime delay, pybind11::object callback);
    /// Whether a pending callback was cancelled.
    bool cancelCallback(std::uint64_t handle);
    /// What `send_denm` asks for: the DEN service's event, as a StoryboardEvent use case sends it.
    struct DenmRequest {
        int cause = 0;
        int subcause = 0;
        double area = 1000;  // m, the geo-broadcast circle's radius around the event
        kernel::SimTime validity;
        kernel::SimTime interval;
        kernel::SimTime repetition;               // how long it is repeated; zero: sent once
        std::optional<Eigen::Vector2d> position;  // the event's; default the station's
        std::optional<double> relevance;
        int trafficClass = 1;
    };
    /// Sends a new DENM event through the station's DEN sender (DenService's); returns its action id.
    facilities::ActionId sendDenm(const DenmRequest& request);
    /// Ends the station's event `action` (a cancellation DENM); false if it is not live.
    bool terminateDenm(const facilities::ActionId& action) { return denms_.terminate(action); }
    /// The phase sbsim's Beacon starts at: uniform in [0, interval), from the seed and the station.
    kernel::SimTime startPhase(kernel::SimTime interval) const;
    const std::string& typeName() const { return typeName_; }

private:
    struct Timer : kernel::Message {
        static constexpr int kKind = 0x5079'5376;
        Timer() : kernel::Message("python service timer", kKind) {}
        std::uint64_t handle = 0;
        pybind11::object callback;
    };
    /// Calls `method` (a name the class defines) with `args`; a Python exception becomes the
    /// service's error, naming the file and line.
    template <typename... Args>
    void call(const pybind11::object& method, const char* name, Args&&... args);
    /// The same, `during` saying what ran ("in Warner.trigger").
    template <typename... Args>
    void callAs(const pybind11::object& method, const std::string& during, Args&&... args);
    /// Hands the messages received since the last batch to indicate_batch().
    void flushBatch();
    pybind11::object method(const char* name) const;

    pybind11::object cls_;
    pybind11::object self_;  // the instance, made at initialize()
    std::string typeName_;   // the class's name, for messages
    // The class's own methods (none: the base's, not called).
    pybind11::object initialize_, trigger_, signal_, indicate_, batch_, cam_, denm_, finish_;
    std::shared_ptr<MessageBatch> pending_;        // batch mode: received since the last batch
    bool batchOnly_ = false;                       // batch mode without on_cam / on_denm
    const radio::V2xMessage* last_ = nullptr;      // the message indicate() took last
    std::shared_ptr<ReceivedMessage> lastRecord_;  // and its copy, for on_cam / on_denm
    std::vector<std::unique_ptr<Timer>> timers_;   // every timer made; idle ones are reused
    std::vector<Timer*> idleTimers_;
    std::unordered_map<std::uint64_t, Timer*> pendingTimers_;  // by handle
    std::uint64_t nextHandle_ = 1;
    std::shared_ptr<PythonService*> alive_;  // what the Python side's handles read; null once gone
    DenmSender denms_{*this};                // its DENMs: action ids, repetition, cancellation
};

}  // namespace sbsim::services::python
