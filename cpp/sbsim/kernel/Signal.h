#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Object.h"

namespace sbsim::kernel {

class Module;
class SignalTable;

/// Signals are identified by small integers registered once per name, as in OMNeT++.
using SignalId = int;

/// Returns the id for `name`, registering it on first use; the same name always gives the same id.
SBSIM_API SignalId registerSignal(std::string_view name);
/// The name a signal id was registered with.
SBSIM_API const std::string& signalName(SignalId id);

/// Receives emitted signals. Override the overloads for the value types you listen to. A listener
/// unsubscribes itself from everything when destroyed, so no table keeps a dangling pointer.
class SBSIM_API Listener {
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
class SBSIM_API SignalTable {
public:
    SignalTable() = default;
    ~SignalTable();
    SignalTable(const SignalTable&) = delete;
    SignalTable& operator=(const SignalTable&) = delete;

    void subscribe(SignalId id, Listener& listener);
    void unsubscribe(SignalId id, Listener& listener);
    bool hasListeners(SignalId id) const {
        return id >= 0 && id < static_cast<SignalId>(listeners_.size()) && !listeners_[id].empty();
    }

    /// Calls the listeners subscribed when the notification starts. One unsubscribed (or destroyed)
    /// meanwhile is not called anymore; one subscribed meanwhile hears the next notification.
    template <typename T>
    void notify(Module& source, SignalId id, const T& value) {
        if (!hasListeners(id)) return;
        const NotifyScope scope(*this);
        // Indexing, not iterators nor a copy: the lists may grow, and a copy could hold a listener
        // destroyed by an earlier one. Unsubscribing only blanks slots while notifying_ > 0.
        const std::size_t n = listeners_[id].size();
        for (std::size_t i = 0; i < n; ++i) {
            if (Listener* l = listeners_[id][i]) l->receiveSignal(source, id, value);
        }
    }

private:
    /// Counts nested notifications; the last one to end drops the blanked slots (also on a throw).
    struct NotifyScope {
        explicit NotifyScope(SignalTable& t) : table(t) { ++table.notifying_; }
        ~NotifyScope() {
            if (--table.notifying_ == 0 && table.blanked_) table.dropBlanked();
        }
        NotifyScope(const NotifyScope&) = delete;
        NotifyScope& operator=(const NotifyScope&) = delete;
        SignalTable& table;
    };
    void dropBlanked();

    std::vector<std::vector<Listener*>> listeners_;  // indexed by SignalId; nullptr: unsubscribed while notifying
    int notifying_ = 0;
    bool blanked_ = false;
};

}  // namespace sbsim::kernel
