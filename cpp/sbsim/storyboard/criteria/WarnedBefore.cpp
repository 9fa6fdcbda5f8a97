#include "sbsim/storyboard/criteria/WarnedBefore.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace sbsim::storyboard {

namespace {
constexpr std::size_t kNamed = 10;  // vehicles named in the verdict; the rest are counted
}

WarnedBefore::WarnedBefore(std::optional<geometry::Polygon> area, std::string edge, std::optional<int> cause,
                           kernel::SimTime lead, kernel::SimTime since, std::optional<kernel::SimTime> until,
                           bool equippedOnly)
    : area_(std::move(area)),
      edge_(std::move(edge)),
      cause_(cause),
      lead_(lead),
      since_(since),
      until_(until),
      equippedOnly_(equippedOnly) {
    if (until && *until < since) throw std::invalid_argument("WarnedBefore needs until >= since");
    if (lead < kernel::SimTime::zero()) throw std::invalid_argument("WarnedBefore needs seconds >= 0");
    if (cause && (*cause < 0 || *cause > 255))
        throw std::invalid_argument(fmt::format("WarnedBefore cause must be a cause code 0 to 255, got {}", *cause));
}

std::shared_ptr<WarnedBefore> WarnedBefore::inArea(geometry::Polygon area, std::optional<int> cause,
                                                   kernel::SimTime lead, kernel::SimTime since,
                                                   std::optional<kernel::SimTime> until, bool equippedOnly) {
    return std::shared_ptr<WarnedBefore>(
        new WarnedBefore(std::move(area), {}, cause, lead, since, until, equippedOnly));
}

std::shared_ptr<WarnedBefore> WarnedBefore::onEdge(std::string edge, std::optional<int> cause, kernel::SimTime lead,
                                                   kernel::SimTime since, std::optional<kernel::SimTime> until,
                                                   bool equippedOnly) {
    if (edge.empty()) throw std::invalid_argument("WarnedBefore needs an edge id or an area, got ''");
    return std::shared_ptr<WarnedBefore>(
        new WarnedBefore(std::nullopt, std::move(edge), cause, lead, since, until, equippedOnly));
}

void WarnedBefore::check(CheckContext& ctx) const {
    if (!area_) ctx.warnUnknown("WarnedBefore", NetworkObject::Edge, {edge_});
}

std::string WarnedBefore::describe() const {
    std::string out = area_ ? fmt::format("WarnedBefore({} points", area_->vertices().size())
                            : fmt::format("WarnedBefore(edge {}", edge_);
    out += cause_ ? fmt::format(", cause={}", *cause_) : "";
    out += fmt::format(", seconds={}", lead_.str());
    if (since_ > kernel::SimTime::zero()) out += fmt::format(", since={}", since_.str());
    if (until_) out += fmt::format(", until={}", until_->str());
    if (equippedOnly_) out += ", equipped_only=True";
    return out + ")";
}

traffic::SnapshotColumns WarnedBefore::columns() const {
    return area_ ? traffic::SnapshotColumns::Position : traffic::SnapshotColumns::Lane;
}

bool WarnedBefore::there(const traffic::VehicleSnapshot& s, traffic::VehicleSnapshot::Index i) const {
    return area_ ? area_->contains(s.positions().col(i)) : s.roadId(i) == edge_;
}

std::optional<kernel::SimTime> WarnedBefore::heard(const EvaluationContext& ctx, const std::string& id) {
    const facilities::StationFacilities* station = ctx.stations() == nullptr ? nullptr : ctx.stations()->find(id);
    if (station == nullptr) return std::nullopt;
    std::optional<kernel::SimTime> first;
    for (const auto& [action, entry] : station->denms.entries()) {
        if (cause_ && entry.denm.cause != *cause_) continue;
        originators_.insert(action.station);
        if (!first || entry.firstHeardAt < *first) first = entry.firstHeardAt;
    }
    return first;
}

void WarnedBefore::observe(const EvaluationContext& ctx) {
    const traffic::VehicleSnapshot& s = ctx.snapshot();
    std::unordered_map<std::string, Track> now;
    now.reserve(s.size());
    for (traffic::VehicleSnapshot::Index i = 0; i < s.size(); ++i) {
        const std::string& id = s.ids()[i];
        if (equippedOnly_ && !ctx.equipped(id)) continue;  // never judged, so never tracked
        const auto known = tracks_.find(id);
        Track track = known == tracks_.end() ? Track{} : known->second;
        if (!track.decided) {
            // Memories are only read for vehicles still on their way: once warned, the first
            // warning is kept (the memory drops events that expire or end).
            if (!track.warnedAt) track.warnedAt = heard(ctx, id);
            if (!there(s, i)) {
                track.wasAway = true;
            } else {
                track.decided = true;
                if (track.wasAway && ctx.now() >= since_ && (!until_ || ctx.now() <= *until_))
                    reached_.push_back({id, ctx.now(), track.warnedAt});
            }
        }
        now.emplace(id, track);
    }
    tracks_ = std::move(now);  // vehicles that left are forgotten
}

CriterionVerdict WarnedBefore::verdict(const CriterionRun& /*run*/) const {
    const std::string expected = fmt::format("0 vehicles reached it unwarned (warned >= {} s before)", lead_.str());
    std::size_t judged = 0;
    std::vector<const Reach*> unwarned;
    std::optional<kernel::SimTime> shortest;  // lead of the warned
    for (const Reach& r : reached_) {
        if (originators_.contains(r.vehicle)) continue;
        ++judged;
        if (r.warnedAt && *r.warnedAt + lead_ <= r.at) {
            const kernel::SimTime ahead = r.at - *r.warnedAt;
            if (!shortest || ahead < *shortest) shortest = ahead;
        } else {
            unwarned.push_back(&r);
        }
    }
    if (judged == 0) return {true, "no vehicle reached it", expected};
    if (unwarned.empty()) {
        return {
            true,
            fmt::format("0 of {} vehicles reached it unwarned (shortest warning {} s ahead)", judged, shortest->str()),
            expected};
    }
    std::string names;
    for (std::size_t k = 0; k < std::min(unwarned.size(), kNamed); ++k) {
        names += (k == 0 ? "" : ", ") + unwarned[k]->vehicle;
    }
    if (unwarned.size() > kNamed) names += fmt::format(" and {} more", unwarned.size() - kNamed);
    const Reach& first = *unwarned.front();
    const std::string how = first.warnedAt ? fmt::format("warned at t={} s", first.warnedAt->str()) : "never warned";
    return {false,
            fmt::format("{} of {} vehicles reached it unwarned ({}), first {} at t={} s, {}", unwarned.size(), judged,
                        names, first.vehicle, first.at.str(), how),
            expected};
}

}  // namespace sbsim::storyboard
