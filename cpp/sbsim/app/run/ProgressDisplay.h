#pragma once

#include <chrono>
#include <cstdio>
#include <optional>

#include "sbsim/kernel/Signal.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::app {

/// One self-overwriting status line on a terminal: sim time / end, running vehicles, steps per
/// second, ETA. Listens to the SUMO step signal; redraws at most four times a second.
class ProgressDisplay : public kernel::Listener {
public:
    /// Shows `snapshot` (the SUMO bridge's) after each step.
    ProgressDisplay(std::FILE* out, std::optional<kernel::SimTime> end, const traffic::VehicleSnapshot& snapshot);
    ~ProgressDisplay() override;

    void receiveSignal(kernel::Module& source, kernel::SignalId id, const kernel::Object& value) override;
    /// Erases the line so the summary starts on a clean one.
    void clear();

private:
    using Clock = std::chrono::steady_clock;
    std::FILE* out_;
    const traffic::VehicleSnapshot& snapshot_;
    std::optional<kernel::SimTime> end_;
    Clock::time_point start_ = Clock::now();
    Clock::time_point lastDraw_{};
    std::optional<kernel::SimTime> firstTime_;
    std::uint64_t steps_ = 0;
    bool drawn_ = false;
};

}  // namespace sbsim::app
