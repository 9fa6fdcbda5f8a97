#include "sbsim/radio/geonet/Router.h"

#include <algorithm>
#include <stdexcept>

namespace sbsim::radio::geonet {

Router::Router(std::string station, RouterSettings settings) : station_(std::move(station)), settings_(settings) {
    if (settings_.hopLimit < 1) throw std::invalid_argument("the GeoNetworking hop limit must be at least 1");
}

void Router::originate(V2xMessage& message, const Eigen::Vector2d& position, const Neighbours& neighbours) {
    PacketHeader& h = header(message);
    if (!h.geoBroadcast()) return;
    h.source = station_;
    h.sequence = nextSequence_++;
    h.maxHopLimit = h.hopLimit = settings_.forwarding ? settings_.hopLimit : 1;
    h.senderPosition = position;
    h.nextHop.clear();
    if (!settings_.forwarding) return;
    (void)duplicates_.seen(h.id());  // heard back from a forwarder, it is a duplicate
    if (h.area.contains(position)) return;
    const std::vector<Neighbour> around = neighbours ? neighbours() : std::vector<Neighbour>{};
    if (const auto next = greedyNextHop(position, h.area.center, around)) h.nextHop = around[*next].station;
}

std::unique_ptr<V2xMessage> Router::forwardCopy(const V2xMessage& message) {
    std::unique_ptr<V2xMessage> copy = message.clone();
    if (!copy) return nullptr;
    PacketHeader& h = header(*copy);
    h = message.geonet();  // a message's copy constructor might not take it along
    --h.hopLimit;
    h.nextHop.clear();
    return copy;
}

Router::Reception Router::receive(const V2xMessage& message, const Eigen::Vector2d& position, kernel::SimTime now,
                                  const Neighbours& neighbours) {
    const PacketHeader& h = message.geonet();
    Reception r;
    if (!h.geoBroadcast()) {
        r.passUp = true;
        return r;
    }
    const bool inside = h.area.contains(position);
    if (!settings_.forwarding) {
        r.passUp = inside;
        return r;
    }
    if (!h.nextHop.empty() && h.nextHop != station_) return r;  // unicast to another station
    const PacketId id = h.id();
    if (duplicates_.seen(id)) {
        r.timersChanged = cancel(id);  // another station forwarded it: this one need not
        return r;
    }
    r.passUp = inside;
    if (h.hopLimit <= 1) return r;  // no hop left
    if (inside) {
        std::unique_ptr<V2xMessage> copy = forwardCopy(message);
        if (!copy) return r;
        const kernel::SimTime due = now + settings_.cbf((position - h.senderPosition).norm());
        buffer_.push_back({due, nextOrder_++, id, std::move(copy)});
        r.timersChanged = true;
        return r;
    }
    // Outside the area: greedy forwarding towards it, but not of a broadcast from inside it.
    if (h.nextHop.empty() && h.area.contains(h.senderPosition)) return r;
    r.forwardNow = forwardCopy(message);
    if (!r.forwardNow) return r;
    PacketHeader& out = header(*r.forwardNow);
    out.senderPosition = position;
    const std::vector<Neighbour> around = neighbours ? neighbours() : std::vector<Neighbour>{};
    if (const auto next = greedyNextHop(position, h.area.center, around)) out.nextHop = around[*next].station;
    return r;
}

bool Router::cancel(const PacketId& id) {
    const auto it = std::find_if(buffer_.begin(), buffer_.end(), [&](const Contending& c) { return c.id == id; });
    if (it == buffer_.end()) return false;
    buffer_.erase(it);
    return true;
}

bool Router::contending(const PacketId& id) const {
    return std::any_of(buffer_.begin(), buffer_.end(), [&](const Contending& c) { return c.id == id; });
}

std::optional<kernel::SimTime> Router::nextTimeout() const {
    if (buffer_.empty()) return std::nullopt;
    return std::min_element(buffer_.begin(), buffer_.end(),
                            [](const Contending& a, const Contending& b) { return a.due < b.due; })
        ->due;
}

std::vector<std::unique_ptr<V2xMessage>> Router::takeExpired(kernel::SimTime now, const Eigen::Vector2d& position) {
    std::vector<Contending> due;
    for (auto it = buffer_.begin(); it != buffer_.end();) {
        if (it->due <= now) {
            due.push_back(std::move(*it));
            it = buffer_.erase(it);
        } else {
            ++it;
        }
    }
    std::sort(due.begin(), due.end(), [](const Contending& a, const Contending& b) {
        return a.due != b.due ? a.due < b.due : a.order < b.order;
    });
    std::vector<std::unique_ptr<V2xMessage>> out;
    out.reserve(due.size());
    for (Contending& c : due) {
        header(*c.packet).senderPosition = position;
        out.push_back(std::move(c.packet));
    }
    return out;
}

}  // namespace sbsim::radio::geonet
