#include "sbsim/app/run/ProgressDisplay.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::app {

namespace {
std::string clockText(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}
}  // namespace

ProgressDisplay::ProgressDisplay(std::FILE* out, std::optional<kernel::SimTime> end,
                                 const traffic::VehicleSnapshot& snapshot)
    : out_(out), snapshot_(snapshot), end_(end) {}

ProgressDisplay::~ProgressDisplay() { clear(); }

void ProgressDisplay::receiveSignal(kernel::Module&, kernel::SignalId, const kernel::Object&) {
    const traffic::VehicleSnapshot* snapshot = &snapshot_;
    ++steps_;
    if (!firstTime_) firstTime_ = snapshot->time();
    const Clock::time_point now = Clock::now();
    if (now - lastDraw_ < std::chrono::milliseconds(250)) return;
    lastDraw_ = now;

    const double wall = std::chrono::duration<double>(now - start_).count();
    const double simulated = (snapshot->time() - *firstTime_).seconds();
    std::string line = fmt::format("t={} s", snapshot->time().str());
    if (end_) line += fmt::format(" / {} s", end_->str());
    line += fmt::format("  running {}  {:.0f} steps/s", snapshot->size(), wall > 0 ? steps_ / wall : 0.0);
    if (end_ && simulated > 0) line += "  ETA " + clockText((*end_ - snapshot->time()).seconds() * wall / simulated);
    fmt::print(out_, "\r\033[K{}", line);
    std::fflush(out_);
    drawn_ = true;
}

void ProgressDisplay::clear() {
    if (!drawn_) return;
    fmt::print(out_, "\r\033[K");
    std::fflush(out_);
    drawn_ = false;
}

}  // namespace sbsim::app
