#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kernel/Object.h"

namespace sbsim::kernel {

class Module;
class SignalTable;

/// Signals are identified by small integers registered once per name, as in OMNeT++.
using SignalId = int;

/// Returns the id for `name`, registering it on first use; the same name always gives the same id.
SignalId registerSignal(std::string_view name);
/// The name a signal id was registered with.
const std::string& signalName(SignalId id);

/// Receives emitted signals. Override the overloads for the value types you listen to. A listener
/// unsubscribes itself from everything when destroyed, so no table keeps a dangling pointer.
class Listener {
public:
    Listener() = default;
    virtual ~Listener();
    Listener(const Listener&) = delete;
    Listener& operator=(const Listener&) = delete;

    virtual void receiveSignal(Module& source, SignalId id, std::int64_t value);
    virtual void receiveSignal(Module& source, SignalId id, double value);
    virtual void receiveSignal(Module& source, SignalId id, std::string_view value);
    virtual void receiveSignal(Module& source, SignalId id, const Object& value);

private:
    friend class SignalTable;
    std::vector<std::pair<SignalTable*, SignalId>> subscriptions_;
};

/// Who listens to which signal: one table per module (local subscriptions) and one in the
/// simulation (listeners to every module's emits, the role of OMNeT++'s system module).
class SignalTable {
public:
    SignalTable() = default;
    ~SignalTable();
    SignalTable(const SignalTable&) = delete;
    SignalTable& operator=(const SignalTable&) = delete;

    void subscribe(SignalId id, Listener& listener);
    void unsubscribe(SignalId id, Listener& listener);
    bool hasListeners(SignalId id) const {
        return id < static_cast<SignalId>(listeners_.size()) && !listeners_[id].empty();
    }

    template <typename T>
    void notify(Module& source, SignalId id, const T& value) const {
        if (!hasListeners(id)) return;
        // A copy: listeners may (un)subscribe while being notified.
        const std::vector<Listener*> targets = listeners_[id];
        for (Listener* l : targets) l->receiveSignal(source, id, value);
    }

private:
    std::vector<std::vector<Listener*>> listeners_;  // indexed by SignalId
};

}  // namespace sbsim::kernel
