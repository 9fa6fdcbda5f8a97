#include "sbsim/app/ProgressDisplay.h"

#include <cmath>
#include <string>

#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::app {

namespace {
std::string clockText(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    char buf[32];
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
    return buf;
}
}  // namespace

ProgressDisplay::ProgressDisplay(std::FILE* out, std::optional<kernel::SimTime> end) : out_(out), end_(end) {}

ProgressDisplay::~ProgressDisplay() { clear(); }

void ProgressDisplay::receiveSignal(kernel::Module&, kernel::SignalId, const kernel::Object& value) {
    const auto* snapshot = dynamic_cast<const traffic::VehicleSnapshot*>(&value);
    if (snapshot == nullptr) return;
    ++steps_;
    if (!firstTime_) firstTime_ = snapshot->time();
    const Clock::time_point now = Clock::now();
    if (now - lastDraw_ < std::chrono::milliseconds(250)) return;
    lastDraw_ = now;

    const double wall = std::chrono::duration<double>(now - start_).count();
    const double simulated = (snapshot->time() - *firstTime_).seconds();
    std::string line = "t=" + snapshot->time().str() + " s";
    if (end_) line += " / " + end_->str() + " s";
    char buf[160];
    std::snprintf(buf, sizeof buf, "  running %d  %.0f steps/s", snapshot->size(), wall > 0 ? steps_ / wall : 0.0);
    line += buf;
    if (end_ && simulated > 0) line += "  ETA " + clockText((*end_ - snapshot->time()).seconds() * wall / simulated);
    std::fprintf(out_, "\r\033[K%s", line.c_str());
    std::fflush(out_);
    drawn_ = true;
}

void ProgressDisplay::clear() {
    if (!drawn_) return;
    std::fprintf(out_, "\r\033[K");
    std::fflush(out_);
    drawn_ = false;
}

}  // namespace sbsim::app
