#include "sbsim/radio/channel/LinkBudget.h"

#include <algorithm>
#include <utility>

#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Decibels.h"
#include "sbsim/radio/Medium.h"

namespace sbsim::radio {

namespace {
/// A neighbourhood is hundreds of links: a few stations make a chunk worth a worker's wake-up.
constexpr std::size_t kStationsPerChunk = 4;
/// A building-crossing test is a few hundred ns: a few links make a chunk worth a wake-up.
constexpr std::size_t kObstacleLinksPerChunk = 8;
constexpr double kDistanceBin = Medium::kDistanceBin;
}  // namespace

LinkBudget::LinkBudget(const ChannelSettings& settings, std::shared_ptr<const Obstacles> obstacles,
                       const ChannelStations& stations, const traffic::VehicleSnapshot& snapshot,
                       const FixedStations& fixed)
    : settings_(settings),
      obstacles_(std::move(obstacles)),
      stations_(stations),
      snapshot_(snapshot),
      fixed_(fixed),
      pathLoss_(settings_.makePathLoss()) {
    fading_.m = settings_.nakagamiM;
    fading_.veinsDistanceRule = settings_.fading == ChannelSettings::Fading::NakagamiVeins;
    // The cutoff: where the mean power plus a margin for shadowing (2 σ) and fading falls below
    // the floor. Path loss grows with distance, so double, then bisect.
    const double margin =
        2 * settings_.shadowingSigmaDb + (settings_.fading == ChannelSettings::Fading::None ? 0.0 : 5.0);
    const auto above = [&](double d) { return meanPowerDbm(d) + margin >= settings_.interferenceFloorDbm; };
    double lo = 1;
    double hi = 2;
    while (above(hi) && hi < 1e5) {
        lo = hi;
        hi *= 2;
    }
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (above(mid) ? lo : hi) = mid;
    }
    cutoff_ = hi;
}

double LinkBudget::meanPowerDbm(double distance) const { return settings_.powerDbm - pathLoss_->lossDb(distance); }

void LinkBudget::addStation() {
    sentInStep_.push_back(0);
    near_.emplace_back();
}

void LinkBudget::newStep() {
    // A station that left keeps its slot (frames may still be on the air) but not its
    // neighbourhood: a long run sees tens of thousands of vehicles.
    for (Slot s = 0; s < static_cast<Slot>(near_.size()); ++s) {
        if (!stations_.present[s] && near_[s].at) near_[s] = Neighbourhood{};
    }
    // Cells of half the cutoff: a query touches about 5x5 cells around the sender.
    grid_.build(snapshot_, std::max(cutoff_ / 2, 1.0));
}

void LinkBudget::start(std::uint64_t seed) {
    if (settings_.shadowingSigmaDb > 0 && settings_.shadowingCorrelation > 0) {
        shadowing_ =
            std::make_unique<CorrelatedShadowing>(settings_.shadowingSigmaDb, settings_.shadowingCorrelation, seed);
    }
}

void LinkBudget::forget(kernel::SimTime now) {
    if (shadowing_) shadowing_->forget(now);
}

void LinkBudget::computeLinks(Slot s, std::uint64_t frameKey, kernel::SimTime now, std::vector<Link>& links,
                              kernel::ParallelFor& pool) {
    // Who is in range, how far, and the mean power (path loss and obstacles) stay the same for
    // all of a sender's frames within one SUMO step: computed once per step, for the likely
    // senders of the step together at its first frame (prepareStep), else at the sender's first.
    if (batchedAt_ != stations_.refreshedAt) prepareStep(s, pool);
    Neighbourhood& near = near_[s];
    if (near.at != stations_.refreshedAt) computeNeighbourhood(s);
    if (near.obstaclesPending) applyObstacles(s, pool);
    if (sentInStep_[s] != step_) {
        sentInStep_[s] = step_;
        sentThisStep_.push_back(s);
    }
    links.resize(near.receivers.size());
    const bool fading = settings_.fading != ChannelSettings::Fading::None;
    const bool shadowing = settings_.shadowingSigmaDb > 0;
    // The pairs are looked up (and made) here, serially; the pool then moves distinct pairs on.
    if (shadowing_) shadowing_->pairs(stations_.keys[s], near.key, now, pairs_);
    // Each link is a pure function of its ends and its key: any split over threads gives the same.
    pool.run(
        near.receivers.size(),
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t k = begin; k < end; ++k) {
                const Slot r = near.receivers[k];
                // Field by field: `link = Link{}` went through a stack temporary whose overlapping
                // stores stalled store-to-load forwarding (a quarter of this loop's time).
                Link& link = links[k];
                link.receiver = r;
                link.distance = near.distance[k];
                link.bin = near.bin[k];
                link.maxInterferenceMw = 0;
                link.counted = false;
                link.halfDuplex = false;
                link.locked = false;
                double dbm = near.meanDbm[k];
                if (shadowing_) {
                    if (k + 4 < end) shadowing_->prefetch(pairs_[k + 4]);
                    dbm += shadowing_->valueDb(pairs_[k], stations_.keys[s], stations_.x[s], stations_.y[s],
                                               near.key[k], stations_.x[r], stations_.y[r]);
                } else if (shadowing) {
                    auto random = CounterRandom::ofFrame(frameKey, near.key[k], DrawPurpose::Shadowing);
                    dbm += settings_.shadowingSigmaDb * random.normal();
                }
                if (fading) {
                    auto random = CounterRandom::ofFrame(frameKey, near.key[k], DrawPurpose::Fading);
                    dbm += fading_.gainDb(link.distance, random);
                }
                link.powerDbm = dbm;
                link.powerMw = dbToLinear(dbm);
            }
        },
        settings_.linksPerChunk);
    linksComputed_ += links.size();
}

void LinkBudget::prepareStep(Slot first, kernel::ParallelFor& pool) {
    batchedAt_ = stations_.refreshedAt;
    ++step_;
    // The stations that sent during the last step most likely send again in this one (a beacon
    // or CAM sends every step or more often): their neighbourhoods in one round on the pool. A
    // neighbourhood is a pure function of the snapshot, so which ones are computed here changes
    // nothing but the time.
    batch_.clear();
    for (const Slot t : sentThisStep_) {
        if (stations_.present[t] && t != first) batch_.push_back(t);
    }
    batch_.push_back(first);
    sentThisStep_.clear();
    pool.run(
        batch_.size(),
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t k = begin; k < end; ++k) computeNeighbourhood(batch_[k]);
        },
        kStationsPerChunk);
}

void LinkBudget::computeNeighbourhood(Slot s) {
    Neighbourhood& near = near_[s];
    near.at = stations_.refreshedAt;
    near.receivers.clear();
    const auto index = snapshot_.indexOf(stations_.ids[s]);
    // The grid's order (by cell, then vehicle index) is the same whatever the thread count,
    // so the receivers need no sorting; the stationary stations follow in their own order.
    const auto take = [&](traffic::VehicleSnapshot::Index j) {
        if (const Slot r = stations_.slotOfIndex[j]; r >= 0 && r != s) near.receivers.push_back(r);
    };
    const FixedStations& fixed = fixed_;
    const auto fixedSelf = index ? std::nullopt : fixed.indexOf(stations_.ids[s]);
    if (index) {
        grid_.forEachWithin(*index, cutoff_, take);
    } else if (fixedSelf) {
        grid_.forEachAround(stations_.x[s], stations_.y[s], cutoff_, take);
    }
    if ((index || fixedSelf) && !fixed.empty()) {
        fixed.forEachWithin({stations_.x[s], stations_.y[s]}, cutoff_, fixedSelf, [&](FixedStations::Index k, double) {
            const auto it = stations_.slotOf.find(fixed.ids()[k]);
            if (it != stations_.slotOf.end() && stations_.present[it->second]) near.receivers.push_back(it->second);
        });
    }
    const std::size_t n = near.receivers.size();
    near.distance.resize(n);
    near.meanDbm.resize(n);
    near.key.resize(n);
    near.bin.resize(n);
    const Eigen::Vector2d from(stations_.x[s], stations_.y[s]);
    const bool obstacles = obstacles_ && obstacles_->size() > 0;
    for (std::size_t k = 0; k < n; ++k) {
        const Slot r = near.receivers[k];
        const Eigen::Vector2d to(stations_.x[r], stations_.y[r]);
        near.distance[k] = (to - from).norm();
        near.meanDbm[k] = settings_.powerDbm - pathLoss_->lossDb(near.distance[k]);
        near.key[k] = stations_.keys[r];
        near.bin[k] = static_cast<std::uint32_t>(near.distance[k] / kDistanceBin);
    }
    near.obstaclesPending = obstacles && n > 0;
}

void LinkBudget::applyObstacles(Slot s, kernel::ParallelFor& pool) {
    // Apart from the step's batch: the batch guesses the step's senders from the last step's,
    // and with CAMs (1 to 10 Hz) half its guesses do not send, so the dearest part waits for the
    // frame. Within the step the snapshot's positions are those the neighbourhood was made from.
    Neighbourhood& near = near_[s];
    if (obstacleStep_ != step_) {
        obstacleStep_ = step_;
        obstacleDb_.newStep();
    }
    obstacleTodo_.clear();
    for (std::size_t k = 0; k < near.receivers.size(); ++k) {
        if (const double* loss = obstacleDb_.find(s, near.receivers[k])) {
            near.meanDbm[k] -= *loss;
        } else {
            obstacleTodo_.push_back(k);
        }
    }
    obstacleTodoDb_.resize(obstacleTodo_.size());
    const Eigen::Vector2d from(stations_.x[s], stations_.y[s]);
    pool.run(
        obstacleTodo_.size(),
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const Slot r = near.receivers[obstacleTodo_[i]];
                obstacleTodoDb_[i] = obstacles_->lossDb(from, {stations_.x[r], stations_.y[r]});
            }
        },
        kObstacleLinksPerChunk);
    for (std::size_t i = 0; i < obstacleTodo_.size(); ++i) {
        const std::size_t k = obstacleTodo_[i];
        near.meanDbm[k] -= obstacleTodoDb_[i];
        obstacleDb_.add(s, near.receivers[k], obstacleTodoDb_[i]);
    }
    near.obstaclesPending = false;
}

}  // namespace sbsim::radio
