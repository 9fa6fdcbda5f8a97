#include "sbsim/app/outputs/MessageTraceFile.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <variant>

namespace sbsim::app {

namespace {
std::string jsonText(std::string_view s) { return nlohmann::json(std::string(s)).dump(); }
}  // namespace

std::string MessageTraceFile::format(const radio::TraceLine& l) {
    using Event = radio::TraceLine::Event;
    std::string s = fmt::format(R"({{"t":{},"event":"{}","type":{},"station":{})", l.t.str(),
                                l.event == Event::Tx   ? "tx"
                                : l.event == Event::Rx ? "rx"
                                                       : "lost",
                                jsonText(l.message->typeName()), jsonText(l.station));
    if (l.event != Event::Tx) s += fmt::format(R"(,"sender":{})", jsonText(l.sender));
    s += fmt::format(R"(,"seq":{})", l.seq);
    switch (l.event) {
        case Event::Tx:
            s += fmt::format(R"(,"bytes":{},"x":{:.2f},"y":{:.2f})", l.message->byteSize(), l.x, l.y);
            if (l.cbr) s += fmt::format(R"(,"cbr":{:.4f})", *l.cbr);
            break;
        case Event::Rx:
            s += fmt::format(R"(,"distance":{:.2f},"delay":{:.9f})", l.distance, l.delay);
            if (l.powerDbm) s += fmt::format(R"(,"power_dbm":{:.2f})", *l.powerDbm);
            if (l.sinrDb) s += fmt::format(R"(,"sinr_db":{:.2f})", *l.sinrDb);
            break;
        case Event::Lost:
            s += fmt::format(R"(,"distance":{:.2f},"reason":"{}")", l.distance, radio::lossReasonName(l.reason));
            break;
    }
    // A geo-broadcast's lines name its source and its hops (`sender` is the station that sent this
    // frame: the source, or the forwarder).
    if (const radio::geonet::PacketHeader& gn = l.message->geonet(); gn.geoBroadcast()) {
        s += fmt::format(R"(,"source":{},"hops":{})", jsonText(gn.source), gn.hops());
        if (!gn.nextHop.empty()) s += fmt::format(R"(,"next_hop":{})", jsonText(gn.nextHop));
    }
    for (const radio::TraceField& field : l.message->traceFields()) {
        s += fmt::format(",{}:", jsonText(field.name));
        std::visit(
            [&](const auto& v) {
                if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>) {
                    s += jsonText(v);
                } else {
                    s += nlohmann::json(v).dump();
                }
            },
            field.value);
    }
    s += '}';
    return s;
}

void MessageTraceFile::writeUpTo(kernel::SimTime now) {
    while (!pending_.empty() && pending_.top().t <= now) {
        out_ << pending_.top().text << '\n';
        pending_.pop();
    }
}

void MessageTraceFile::record(const radio::TraceLine& line, kernel::SimTime now) {
    // Nothing reported later can be earlier than now, so what waits up to now can go.
    writeUpTo(now);
    if (line.t <= now && pending_.empty()) {
        out_ << format(line) << '\n';
        return;
    }
    pending_.push({line.t, order_++, format(line)});
    writeUpTo(now);
}

void MessageTraceFile::denmPhase(const facilities::DenmPhaseEvent& event) {
    writeUpTo(event.time);
    out_ << fmt::format(R"({{"t":{},"event":"denm","phase":"{}","station":{},"action":{},"cause":{}}})",
                        event.time.str(), facilities::phaseName(event.phase), jsonText(event.station),
                        jsonText(event.action.str()), event.cause)
         << '\n';
}

void MessageTraceFile::finish(kernel::SimTime end) {
    writeUpTo(end);
    pending_ = {};
}

}  // namespace sbsim::app
