#pragma once

#include <functional>
#include <utility>

#include "sbsim/kernel/Signal.h"

namespace sbsim::app {

/// Runs a function after every SUMO step (subscribe it to SumoBridge::stepSignal): the program's
/// own checks between steps, such as a requested interruption or a failed output.
class AfterEachStep : public kernel::Listener {
public:
    explicit AfterEachStep(std::function<void()> check) : check_(std::move(check)) {}
    void receiveSignal(kernel::Module&, kernel::SignalId, const kernel::Object&) override { check_(); }

private:
    std::function<void()> check_;
};

}  // namespace sbsim::app
