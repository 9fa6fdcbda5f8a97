#include "sbsim/storyboard/EventLog.h"

#include <nlohmann/json.hpp>

namespace sbsim::storyboard {

namespace {

// Ordered: every line lists t, type, story, vehicle first, then what the event type adds.
using Event = nlohmann::ordered_json;

// Seconds rounded to the millisecond: an integer on whole seconds, else ms / 1000, which the
// shortest round-trip printing turns into e.g. 12.3 or 7.001.
Event seconds(kernel::SimTime t) {
    constexpr kernel::SimTime::rep kPerMs = 1'000'000;
    const kernel::SimTime::rep raw = t.raw();
    const kernel::SimTime::rep ms = raw >= 0 ? (raw + kPerMs / 2) / kPerMs : -((-raw + kPerMs / 2) / kPerMs);
    if (ms % 1000 == 0) return ms / 1000;
    return static_cast<double>(ms) / 1000.0;
}

// Key by key rather than from an initializer list, which builds a temporary array per pair and
// made each line twice as slow.
Event event(kernel::SimTime t, std::string_view type, std::optional<std::string_view> story,
            std::optional<std::string_view> vehicle) {
    Event e;
    e["t"] = seconds(t);
    e["type"] = type;
    e["story"] = story ? Event(*story) : Event(nullptr);
    e["vehicle"] = vehicle ? Event(*vehicle) : Event(nullptr);
    return e;
}

// One line. Invalid UTF-8 (story names and causes come from scripts, ids from SUMO files) is
// replaced rather than thrown mid-run.
std::string line(const Event& e) { return e.dump(-1, ' ', false, Event::error_handler_t::replace) + '\n'; }

}  // namespace

void EventLog::write(const std::string& text) {
    out_ << text;
    if (keep_) kept_ += text;
}

void EventLog::activate(kernel::SimTime t, std::string_view story, std::optional<std::string_view> vehicle) {
    write(line(event(t, "activate", story, vehicle)));
}

void EventLog::deactivate(kernel::SimTime t, std::string_view story, std::optional<std::string_view> vehicle,
                          std::string_view reason) {
    Event e = event(t, "deactivate", story, vehicle);
    e["reason"] = reason;
    write(line(e));
}

void EventLog::equipped(kernel::SimTime t, std::string_view vehicle) {
    write(line(event(t, "equipped", std::nullopt, vehicle)));
}

void EventLog::signal(kernel::SimTime t, std::string_view story, std::string_view vehicle, std::string_view cause,
                      const std::vector<std::string>& others, bool onExit) {
    Event e = event(t, "signal", story, vehicle);
    e["cause"] = cause;
    e["others"] = others;
    if (onExit) e["phase"] = "exit";
    write(line(e));
}

}  // namespace sbsim::storyboard
