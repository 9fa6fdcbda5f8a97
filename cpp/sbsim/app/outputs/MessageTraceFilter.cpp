#include "sbsim/app/outputs/MessageTraceFilter.h"

namespace sbsim::app {

namespace {
constexpr std::pair<std::string_view, MessageTraceFilter::Event> kEvents[] = {
    {"tx", MessageTraceFilter::Event::Tx},     {"rx", MessageTraceFilter::Event::Rx},
    {"lost", MessageTraceFilter::Event::Lost}, {"denm", MessageTraceFilter::Event::Denm},
    {"dcc", MessageTraceFilter::Event::Dcc},
};
}  // namespace

std::optional<MessageTraceFilter::Event> MessageTraceFilter::eventNamed(std::string_view name) {
    for (const auto& [n, e] : kEvents) {
        if (n == name) return e;
    }
    return std::nullopt;
}

std::string_view MessageTraceFilter::eventName(Event event) {
    for (const auto& [n, e] : kEvents) {
        if (e == event) return n;
    }
    return "?";
}

std::string MessageTraceFilter::eventNames() {
    std::string out;
    for (const auto& [n, e] : kEvents) out += (out.empty() ? "" : ", ") + std::string(n);
    return out;
}

}  // namespace sbsim::app
