#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace sbsim::app {

/// Which lines the message trace keeps (--messages-types, --messages-events): by event (tx, rx,
/// lost, denm) and by message type (a `denm` line counts as type DENM). By default every type
/// and every event but `lost`: lost receptions outnumber the rest several times over and are
/// written only when asked for.
class MessageTraceFilter {
public:
    enum class Event { Tx, Rx, Lost, Denm, Dcc };

    static std::optional<Event> eventNamed(std::string_view name);
    static std::string_view eventName(Event event);
    /// "tx, rx, lost, denm": for messages.
    static std::string eventNames();

    MessageTraceFilter() = default;
    /// Keeps exactly these events.
    void setEvents(const std::set<Event>& events) { events_ = events; }
    /// Keeps only these message types (none given: all).
    void setTypes(std::set<std::string, std::less<>> types) { types_ = std::move(types); }

    bool keeps(Event event) const { return events_.count(event) > 0; }
    bool keeps(Event event, std::string_view type) const {
        return keeps(event) && (types_.empty() || types_.find(type) != types_.end());
    }
    const std::set<Event>& events() const { return events_; }
    const std::set<std::string, std::less<>>& types() const { return types_; }

private:
    std::set<Event> events_{Event::Tx, Event::Rx, Event::Denm, Event::Dcc};
    std::set<std::string, std::less<>> types_;
};

}  // namespace sbsim::app
