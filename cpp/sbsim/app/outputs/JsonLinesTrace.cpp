#include "sbsim/app/outputs/JsonLinesTrace.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <variant>

namespace sbsim::app {

namespace {
std::string jsonText(std::string_view s) { return nlohmann::json(std::string(s)).dump(); }
}  // namespace

std::string JsonLinesTrace::format(const TraceRecord& l) {
    using Event = TraceRecord::Event;
    if (l.event == Event::Dcc) {
        return fmt::format(R"({{"t":{},"event":"dcc","station":{},"state":"{}","cbr":{:.4f},"interval":{}}})",
                           l.t.str(), jsonText(l.station), l.dccState, l.cbr.value_or(0), l.dccInterval);
    }
    if (l.event == Event::Denm) {
        return fmt::format(R"({{"t":{},"event":"denm","phase":"{}","station":{},"action":{},"cause":{}}})", l.t.str(),
                           l.phase, jsonText(l.station), jsonText(l.action), l.cause);
    }
    std::string s = fmt::format(R"({{"t":{},"event":"{}","type":{},"station":{})", l.t.str(),
                                MessageTraceFilter::eventName(l.event), jsonText(l.type), jsonText(l.station));
    if (l.event != Event::Tx) s += fmt::format(R"(,"sender":{})", jsonText(l.sender));
    s += fmt::format(R"(,"seq":{})", l.seq);
    switch (l.event) {
        case Event::Tx:
            s += fmt::format(R"(,"bytes":{},"frame_bytes":{},"x":{:.2f},"y":{:.2f})", l.bytes, l.frameBytes, l.x, l.y);
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
        case Event::Denm:
        case Event::Dcc:
            break;
    }
    // A geo-broadcast's lines name its source and its hops (`sender` is the station that sent this
    // frame: the source, or the forwarder).
    if (l.geoBroadcast) {
        s += fmt::format(R"(,"source":{},"hops":{})", jsonText(l.source), l.hops);
        if (!l.nextHop.empty()) s += fmt::format(R"(,"next_hop":{})", jsonText(l.nextHop));
    }
    for (const radio::TraceField& field : l.fields) {
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

bool JsonLinesTrace::write(const TraceRecord& line, std::uint64_t budget) {
    const std::string text = format(line);
    if (bytes_ + text.size() + 1 > budget) return false;
    out_ << text << '\n';
    bytes_ += text.size() + 1;
    return true;
}

}  // namespace sbsim::app
