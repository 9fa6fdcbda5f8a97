#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Object.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::kernel {

class FutureEventSet;
class Module;

/// An event: a message that arrives at a module at a simulation time. Self-messages (timers) are
/// owned by the module that schedules them and are never copied; a message still scheduled when
/// it is destroyed removes itself from the future-event set.
class SBSIM_API Message : public Object {
public:
    explicit Message(std::string name = {}, int kind = 0) : name_(std::move(name)), kind_(kind) {}
    ~Message() override;
    Message(const Message&) = delete;
    Message& operator=(const Message&) = delete;

    const std::string& name() const { return name_; }
    int kind() const { return kind_; }
    /// Among events at the same time, a smaller priority value is delivered first.
    int priority() const { return priority_; }
    void setPriority(int priority);

    bool isScheduled() const { return heapIndex_ != kNotScheduled; }
    SimTime arrivalTime() const { return arrival_; }
    Module* arrivalModule() const { return target_; }

private:
    friend class FutureEventSet;
    static constexpr std::size_t kNotScheduled = std::numeric_limits<std::size_t>::max();

    std::string name_;
    int kind_ = 0;
    int priority_ = 0;
    SimTime arrival_;
    std::uint64_t insertionOrder_ = 0;
    std::size_t heapIndex_ = kNotScheduled;
    FutureEventSet* fes_ = nullptr;
    Module* target_ = nullptr;
    bool ownedBySet_ = false;  // handed over with a unique_ptr: the set frees it unless delivered
};

}  // namespace sbsim::kernel
