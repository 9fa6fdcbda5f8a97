#pragma once

#include <memory>
#include <string>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Message.h"
#include "sbsim/kernel/Signal.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::kernel {

class Simulation;

/// A simulation component with OMNeT++'s small lifecycle: initialize() once when the simulation
/// starts (or when added to a running one), handleMessage() for each event addressed to it,
/// finish() once at the end. Modules are owned by their Simulation.
class SBSIM_API Module {
public:
    explicit Module(std::string name) : name_(std::move(name)) {}
    virtual ~Module();
    Module(const Module&) = delete;
    Module& operator=(const Module&) = delete;

    const std::string& name() const { return name_; }
    Simulation& simulation() const;
    SimTime simTime() const;

    /// Listen to the signals this module emits.
    void subscribe(SignalId id, Listener& listener) { signals_.subscribe(id, listener); }
    void unsubscribe(SignalId id, Listener& listener) { signals_.unsubscribe(id, listener); }
    /// Whether an emit of `id` would reach anyone (here or simulation-wide): lets a module skip
    /// building a payload nobody reads.
    bool hasListeners(SignalId id) const;

    virtual void initialize() {}
    virtual void handleMessage(Message& msg);
    virtual void finish() {}

    /// Called inside the handler of an exception that this module's initialize(), handleMessage()
    /// or finish() threw: a module running a user's code (a service) throws an error naming
    /// itself instead. The default rethrows the exception as it is.
    [[noreturn]] virtual void failed() { throw; }

protected:
    /// For modules named after construction (services are named for their vehicle).
    void setName(std::string name) { name_ = std::move(name); }
    /// Self-message (timer) at absolute time `at`; `msg` stays owned by the caller.
    void scheduleAt(SimTime at, Message& msg);
    void scheduleAfter(SimTime delay, Message& msg) { scheduleAt(simTime() + delay, msg); }
    /// Unschedules `msg` if it is scheduled; a no-op otherwise.
    void cancelEvent(Message& msg);
    /// Hands `msg` to `target`, arriving after `delay`; the kernel owns it until delivery.
    void sendDirect(std::unique_ptr<Message> msg, SimTime delay, Module& target);

    /// Notifies this module's listeners, then the simulation-wide ones.
    template <typename T>
    void emit(SignalId id, const T& value);
    void emit(SignalId id, const char* value) { emit(id, std::string_view(value)); }
    void emit(SignalId id, int value) { emit(id, static_cast<std::int64_t>(value)); }

private:
    friend class Simulation;
    std::string name_;
    Simulation* simulation_ = nullptr;
    bool initialized_ = false;
    SignalTable signals_;
};

}  // namespace sbsim::kernel

#include "sbsim/kernel/Simulation.h"

namespace sbsim::kernel {

inline bool Module::hasListeners(SignalId id) const {
    return signals_.hasListeners(id) || (simulation_ != nullptr && simulation_->signals().hasListeners(id));
}

template <typename T>
void Module::emit(SignalId id, const T& value) {
    signals_.notify(*this, id, value);
    if (simulation_ != nullptr) simulation_->signals().notify(*this, id, value);
}

}  // namespace sbsim::kernel
