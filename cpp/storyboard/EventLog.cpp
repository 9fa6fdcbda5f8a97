#include "sbsim/storyboard/EventLog.h"

#include <cstdio>

namespace sbsim::storyboard {

std::string EventLog::quote(std::string_view s) {
    std::string out;
    out.reserve(s.size() + 2);
    out.push_back('"');
    for (const char c : s) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
                    out += buf;
                } else {
                    out.push_back(c);
                }
        }
    }
    out.push_back('"');
    return out;
}

std::string EventLog::seconds(kernel::SimTime t) {
    constexpr kernel::SimTime::rep kPerMs = 1'000'000;
    const kernel::SimTime::rep raw = t.raw();
    const kernel::SimTime::rep ms = raw >= 0 ? (raw + kPerMs / 2) / kPerMs : -((-raw + kPerMs / 2) / kPerMs);
    return kernel::SimTime::fromMilliseconds(ms).str();
}

void EventLog::begin(kernel::SimTime t, std::string_view type, std::string_view story, std::string_view vehicle) {
    out_ << "{\"t\": " << seconds(t) << ", \"type\": \"" << type << "\", \"story\": " << quote(story)
         << ", \"vehicle\": " << quote(vehicle);
}

void EventLog::activate(kernel::SimTime t, std::string_view story, std::string_view vehicle) {
    begin(t, "activate", story, vehicle);
    out_ << "}\n";
}

void EventLog::deactivate(kernel::SimTime t, std::string_view story, std::string_view vehicle,
                          std::string_view reason) {
    begin(t, "deactivate", story, vehicle);
    out_ << ", \"reason\": " << quote(reason) << "}\n";
}

void EventLog::signal(kernel::SimTime t, std::string_view story, std::string_view vehicle, std::string_view cause,
                      const std::vector<std::string>& others) {
    begin(t, "signal", story, vehicle);
    out_ << ", \"cause\": " << quote(cause) << ", \"others\": [";
    for (std::size_t i = 0; i < others.size(); ++i) out_ << (i ? ", " : "") << quote(others[i]);
    out_ << "]}\n";
}

}  // namespace sbsim::storyboard
