#include "sbsim/traffic/SignalLinks.h"

#include <libsumo/Lane.h>
#include <libsumo/TrafficLight.h>

namespace sbsim::traffic {

namespace {

/// The lane's edge: SUMO names lane k of edge e "e_k".
std::string edgeOfLaneName(const std::string& lane) {
    const auto cut = lane.rfind('_');
    return cut == std::string::npos ? lane : lane.substr(0, cut);
}

}  // namespace

SignalLinks SignalLinks::ofLoadedSumo() {
    SignalLinks out;
    for (const std::string& signal : libsumo::TrafficLight::getIDList()) {
        const std::vector<std::vector<libsumo::TraCILink>> links = libsumo::TrafficLight::getControlledLinks(signal);
        for (std::size_t index = 0; index < links.size(); ++index) {
            for (const libsumo::TraCILink& l : links[index]) {
                // A link's junction passage can be split (an internal junction where left turns
                // wait): follow the internal lanes from the first (via), each naming the next as
                // its connection's approachedInternal, until the one leading to the target lane.
                std::vector<std::string> internal;
                for (std::string lane = l.viaLane; !lane.empty() && internal.size() < 8;) {
                    internal.push_back(lane);
                    const std::vector<libsumo::TraCIConnection> next = libsumo::Lane::getLinks(lane);
                    lane = next.empty() ? std::string() : next.front().approachedInternal;
                }
                out.add({signal, static_cast<int>(index)}, l.fromLane, internal, l.toLane);
            }
        }
    }
    return out;
}

void SignalLinks::add(const Link& link, const std::string& from, const std::vector<std::string>& internal,
                      const std::string& to) {
    approaches_[from].push_back({link, to, edgeOfLaneName(to)});
    for (const std::string& lane : internal) internal_.emplace(lane, link);
}

std::optional<SignalLinks::Link> SignalLinks::passed(const std::string& from, const std::string& now) const {
    const auto approach = approaches_.find(from);
    if (approach == approaches_.end()) return std::nullopt;
    if (const auto it = internal_.find(now); it != internal_.end()) return it->second;
    for (const Target& t : approach->second) {
        if (t.lane == now) return t.link;
    }
    return std::nullopt;
}

std::optional<SignalLinks::Link> SignalLinks::toward(const std::string& from, const std::string& toEdge) const {
    const auto approach = approaches_.find(from);
    if (approach == approaches_.end()) return std::nullopt;
    for (const Target& t : approach->second) {
        if (t.edge == toEdge) return t.link;
    }
    return std::nullopt;
}

}  // namespace sbsim::traffic
