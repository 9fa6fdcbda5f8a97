#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::traffic {

/// The links a traffic light controls, by the lanes a vehicle is on before and after it passes a
/// link's stop line: which (signal, link index) a move from an approach lane onto the junction
/// (its internal lanes) or beyond it went through. Built once from a loaded SUMO, or by hand.
class SBSIM_API SignalLinks {
public:
    struct Link {
        std::string signal;  ///< the traffic light's id
        int index = 0;       ///< the link's position in the light's state string
    };

    /// Asks libsumo for every traffic light's controlled links; call after SumoBridge::load.
    static SignalLinks ofLoadedSumo();

    /// Link `index` of `signal` leads from lane `from` over `internal` (the junction's internal
    /// lanes in driving order, none without internal links) to lane `to`.
    void add(const Link& link, const std::string& from, const std::vector<std::string>& internal,
             const std::string& to);

    /// Whether lane `from` ends at a traffic light's stop line.
    bool isApproach(const std::string& from) const { return approaches_.contains(from); }
    /// The link passed by a vehicle that was on approach lane `from` and is now on lane `now`,
    /// which is one of the junction's internal lanes or the link's target lane. An internal lane
    /// belongs to one link whatever lane the vehicle came from (it may have changed lanes and
    /// passed the line in one step). None when `from` is no approach or `now` lies on no link of it.
    std::optional<Link> passed(const std::string& from, const std::string& now) const;
    /// The link from approach lane `from` to a lane of edge `toEdge` (for a vehicle that went
    /// beyond the link's target lane within one step), if any.
    std::optional<Link> toward(const std::string& from, const std::string& toEdge) const;

private:
    struct Target {
        Link link;
        std::string lane, edge;
    };
    std::unordered_map<std::string, std::vector<Target>> approaches_;  // by approach lane
    std::unordered_map<std::string, Link> internal_;                   // by internal lane
};

}  // namespace sbsim::traffic
