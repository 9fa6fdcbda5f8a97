#include "sbsim/radio/propagation/CorrelatedShadowing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "sbsim/radio/CounterRandom.h"

namespace sbsim::radio {

std::size_t CorrelatedShadowing::KeyHash::operator()(const Key& k) const {
    return static_cast<std::size_t>(CounterRandom::mix(k.lo ^ CounterRandom::mix(k.hi)));
}

CorrelatedShadowing::CorrelatedShadowing(double sigmaDb, double correlationDistance, std::uint64_t seed)
    : sigmaDb_(sigmaDb), correlationDistance_(correlationDistance), seed_(seed) {
    if (!(sigmaDb >= 0)) throw std::invalid_argument("shadowing sigma must be >= 0 dB");
    if (!(correlationDistance > 0)) throw std::invalid_argument("shadowing correlation distance must be > 0 m");
}

CorrelatedShadowing::Index CorrelatedShadowing::pair(std::uint64_t a, std::uint64_t b, kernel::SimTime now) {
    const Key key{std::min(a, b), std::max(a, b)};
    auto [it, inserted] = byKey_.try_emplace(key, 0);
    if (inserted) {
        if (free_.empty()) {
            it->second = static_cast<Index>(states_.size());
            states_.emplace_back();
        } else {
            it->second = free_.back();
            free_.pop_back();
            states_[it->second] = State{};
        }
        states_[it->second].key = key;
    }
    states_[it->second].seen = now;
    return it->second;
}

double CorrelatedShadowing::valueDb(Index pair, std::uint64_t a, double ax, double ay, std::uint64_t b, double bx,
                                    double by) {
    State& s = states_[pair];
    if (a > b) {  // the pair's own order: its first station has the smaller key
        std::swap(ax, bx);
        std::swap(ay, by);
    }
    // The pair's n-th value draws from (seed, pair, n) and nothing else.
    const auto draw = [&] {
        return CounterRandom(seed_, s.key.lo, s.draws++, s.key.hi, DrawPurpose::CorrelatedShadowing).normal();
    };
    if (s.fresh) {
        s.z = draw();
        s.fresh = false;
    } else {
        const double moved = std::hypot(ax - s.loX, ay - s.loY) + std::hypot(bx - s.hiX, by - s.hiY);
        if (moved > 0) {
            const double rho = std::exp(-moved / correlationDistance_);
            s.z = rho * s.z + std::sqrt(1 - rho * rho) * draw();
        }
    }
    s.loX = ax;
    s.loY = ay;
    s.hiX = bx;
    s.hiY = by;
    return sigmaDb_ * s.z;
}

void CorrelatedShadowing::forget(kernel::SimTime now) {
    if (now - lastSweep_ < kForgetAfter) return;
    lastSweep_ = now;
    for (auto it = byKey_.begin(); it != byKey_.end();) {
        if (now - states_[it->second].seen > kForgetAfter) {
            free_.push_back(it->second);
            it = byKey_.erase(it);
        } else {
            ++it;
        }
    }
}

}  // namespace sbsim::radio
