#include "sbsim/app/outputs/DenmTrace.h"

#include <nlohmann/json.hpp>

namespace sbsim::app {

void DenmTrace::denmPhase(const facilities::DenmPhaseEvent& event) {
    nlohmann::ordered_json line;
    // Milliseconds, as the event log: the medium's latency is 1 ms by default.
    const auto ms = (event.time.raw() + 500'000) / 1'000'000;
    if (ms % 1000 == 0) {
        line["t"] = ms / 1000;
    } else {
        line["t"] = static_cast<double>(ms) / 1000.0;
    }
    line["event"] = "denm";
    line["phase"] = facilities::phaseName(event.phase);
    line["station"] = event.station;
    line["action"] = event.action.str();
    line["cause"] = event.cause;
    out_ << line.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << '\n';
}

}  // namespace sbsim::app
