#include "sbsim/kernel/Signal.h"

#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <unordered_map>

namespace sbsim::kernel {

namespace {
struct Registry {
    std::mutex mutex;
    std::unordered_map<std::string, SignalId> ids;
    std::deque<std::string> names;  // a deque: signalName() hands out references that must survive growth
};
Registry& registry() {
    static Registry r;
    return r;
}
}  // namespace

SignalId registerSignal(std::string_view name) {
    Registry& r = registry();
    const std::lock_guard lock(r.mutex);
    const auto [it, inserted] = r.ids.try_emplace(std::string(name), static_cast<SignalId>(r.names.size()));
    if (inserted) r.names.emplace_back(name);
    return it->second;
}

const std::string& signalName(SignalId id) {
    Registry& r = registry();
    const std::lock_guard lock(r.mutex);
    if (id < 0 || id >= static_cast<SignalId>(r.names.size())) {
        throw std::out_of_range(fmt::format("unknown signal id {}", id));
    }
    return r.names[id];
}

Listener::~Listener() {
    // Copy: unsubscribe edits subscriptions_.
    const auto subs = subscriptions_;
    for (const auto& [table, id] : subs) table->unsubscribe(id, *this);
}

void Listener::receiveSignal(Module&, SignalId, std::int64_t) {}
void Listener::receiveSignal(Module&, SignalId, double) {}
void Listener::receiveSignal(Module&, SignalId, std::string_view) {}
void Listener::receiveSignal(Module&, SignalId, const Object&) {}

SignalTable::~SignalTable() {
    for (SignalId id = 0; id < static_cast<SignalId>(listeners_.size()); ++id) {
        for (Listener* l : listeners_[id]) {
            if (l != nullptr) std::erase(l->subscriptions_, std::pair{this, id});
        }
    }
}

void SignalTable::subscribe(SignalId id, Listener& listener) {
    if (id < 0) throw std::invalid_argument("invalid signal id");
    if (id >= static_cast<SignalId>(listeners_.size())) listeners_.resize(id + 1);
    auto& list = listeners_[id];
    if (std::find(list.begin(), list.end(), &listener) != list.end()) return;
    list.push_back(&listener);
    listener.subscriptions_.emplace_back(this, id);
}

void SignalTable::unsubscribe(SignalId id, Listener& listener) {
    if (id < 0 || id >= static_cast<SignalId>(listeners_.size())) return;
    auto& list = listeners_[id];
    if (notifying_ > 0) {
        // A notification may be iterating this list: keep the slots where they are.
        std::replace(list.begin(), list.end(), &listener, static_cast<Listener*>(nullptr));
        blanked_ = true;
    } else {
        std::erase(list, &listener);
    }
    std::erase(listener.subscriptions_, std::pair{this, id});
}

void SignalTable::dropBlanked() {
    for (auto& list : listeners_) std::erase(list, nullptr);
    blanked_ = false;
}

}  // namespace sbsim::kernel
