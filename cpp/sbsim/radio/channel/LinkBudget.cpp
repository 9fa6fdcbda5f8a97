#include "sbsim/radio/channel/LinkBudget.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Decibels.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/channel/Reception.h"

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
      pathLoss_(settings_.makePathLoss()),
      cells_(settings_.farCellM > 0 ? settings_.farCellM : 1.0) {
    fading_.m = settings_.nakagamiM;
    fading_.veinsDistanceRule = settings_.fading == ChannelSettings::Fading::NakagamiVeins;
    // The cutoff: where the mean power plus a margin for shadowing (2 σ) and fading falls below
    // the floor. Path loss grows with distance, so double, then bisect.
    floorMarginDb_ = 2 * settings_.shadowingSigmaDb + (settings_.fading == ChannelSettings::Fading::None ? 0.0 : 5.0);
    // E[10^(σZ/10)] = exp((σ ln10 / 10)² / 2): an interference-only link adds its mean in mW.
    meanGainDb_ = settings_.shadowingSigmaDb * settings_.shadowingSigmaDb * std::log(10.0) / 20;
    floorMw_ = dbToLinear(settings_.interferenceFloorDbm);
    const auto above = [&](double d) { return meanPowerDbm(d) + floorMarginDb_ >= settings_.interferenceFloorDbm; };
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
    // The far range: from where the mean power stays below the interference-only tier's bound up
    // to the cutoff (scanned: not every law falls monotonically), and no nearer than the trace's
    // range (links there have their lost lines). Buildings lower links one by one: no far tier.
    far_ = settings_.linkTiers && settings_.farCellM > 0 && !(obstacles_ && obstacles_->size() > 0);
    if (far_) {
        const double fullFrom =
            std::min(settings_.sensingDbm - settings_.tierMarginDb, settings_.sensingDbm - meanGainDb_);
        double d = cutoff_;
        while (d > 1 && meanPowerDbm(d - 1) < fullFrom) d -= 1;
        farRange_ = std::max(d, settings_.traceRange);
        far_ = farRange_ < cutoff_;
    }
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
    if (far_) cells_.newStep(stations_);
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

std::shared_ptr<const StepLinks> LinkBudget::computeLinks(Slot s, std::uint64_t frameKey, kernel::SimTime now,
                                                          std::vector<Link>& links, kernel::ParallelFor& pool) {
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
    const StepLinks& step = *near.links;
    const std::size_t n = near.full.size();
    links.resize(n);
    const bool fading = settings_.fading != ChannelSettings::Fading::None;
    const bool shadowing = settings_.shadowingSigmaDb > 0;
    // The pairs are looked up (and made) here, serially, once a step: a frame's links then only
    // touch them, and the pool moves distinct pairs on.
    if (shadowing_ && (near.pairsAt != near.at || near.pairsGeneration != shadowing_->generation())) {
        findPairs(s, near, now);
    }
    // Each link is a pure function of its ends and its key: any split over threads gives the same.
    pool.run(
        n,
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t j = begin; j < end; ++j) {
                const std::size_t k = near.full[j];
                // Field by field: `link = Link{}` went through a stack temporary whose overlapping
                // stores stalled store-to-load forwarding (a quarter of this loop's time).
                Link& link = links[j];
                const Slot r = step.receivers[k];
                link.receiver = r;
                link.distance = step.distance[k];
                link.bin = step.bin[k];
                link.cell = far_ ? cells_.cellOf(r) : -1;
                link.maxInterferenceMw = 0;
                link.counted = false;
                link.halfDuplex = false;
                link.locked = false;
                double dbm = near.fullMeanDbm[j];
                if (shadowing_) {
                    constexpr std::size_t ahead = CorrelatedShadowing::kPrefetchAhead;
                    if (j + ahead < end) shadowing_->prefetch(near.pair[j + ahead]);
                    shadowing_->touch(near.pair[j], now);
                    dbm += shadowing_->valueDb(near.pair[j], stations_.keys[s], stations_.x[s], stations_.y[s],
                                               near.fullKey[j], stations_.x[r], stations_.y[r]);
                } else if (shadowing) {
                    auto random = CounterRandom::ofFrame(frameKey, near.fullKey[j], DrawPurpose::Shadowing);
                    dbm += settings_.shadowingSigmaDb * random.normal();
                }
                if (fading) {
                    auto random = CounterRandom::ofFrame(frameKey, near.fullKey[j], DrawPurpose::Fading);
                    dbm += fading_.gainDb(link.distance, random);
                }
                link.powerDbm = dbm;
                link.powerMw = dbToLinear(dbm);
            }
        },
        settings_.linksPerChunk);
    tiers_.full += n;
    tiers_.interference += step.size() - n;
    for (const std::uint32_t occupants : step.farOccupants) tiers_.interference += occupants;
    tiers_.skipped += near.skipped;
    return near.links;
}

void LinkBudget::findPairs(Slot s, Neighbourhood& near, kernel::SimTime now) {
    const std::uint64_t self = stations_.keys[s];
    if (near.pairsGeneration != shadowing_->generation() || near.pairKeys.empty()) {
        shadowing_->pairs(self, near.fullKey, now, near.pair);
    } else {
        // An index is the pair's for as long as no sweep freed pairs (the generation): the last
        // step's is as good as a lookup, and the same pair.
        constexpr std::size_t kWindow = 4;
        const std::vector<std::uint64_t>& old = near.pairKeys;
        std::vector<CorrelatedShadowing::Index>& out = near.scratch;
        out.resize(near.fullKey.size());
        std::size_t p = 0;
        for (std::size_t k = 0; k < near.fullKey.size(); ++k) {
            const std::uint64_t key = near.fullKey[k];
            std::size_t q = p;
            const std::size_t last = std::min(old.size(), p + kWindow);
            while (q < last && old[q] != key) ++q;
            if (q < last) {
                out[k] = near.pair[q];
                p = q + 1;
            } else {
                out[k] = shadowing_->pair(self, key, now);
            }
        }
        near.pair.swap(out);
    }
    near.pairKeys = near.fullKey;
    near.pairsAt = near.at;
    near.pairsGeneration = shadowing_->generation();
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

namespace {
/// computeNeighbourhood()'s kept vehicles and far cells, one set per thread (a neighbourhood is
/// computed on one).
struct NearScratch {
    std::vector<ChannelStations::Slot> kept;
    FarCells::BeyondTable table;
};
[[gnu::noinline]] NearScratch& nearScratch() {
    static thread_local NearScratch scratch;
    return scratch;
}
}  // namespace

void LinkBudget::computeNeighbourhood(Slot s) {
    Neighbourhood& near = near_[s];
    near.at = stations_.refreshedAt;
    std::vector<Slot>& candidates = near.candidates;
    candidates.clear();
    const auto index = snapshot_.indexOf(stations_.ids[s]);
    // The grid's order (by cell, then vehicle index) is the same whatever the thread count,
    // so the receivers need no sorting; the stationary stations follow in their own order.
    const auto take = [&](traffic::VehicleSnapshot::Index j) {
        if (const Slot r = stations_.slotOfIndex[j]; r >= 0 && r != s) candidates.push_back(r);
    };
    const FixedStations& fixed = fixed_;
    const auto fixedSelf = index ? std::nullopt : fixed.indexOf(stations_.ids[s]);
    // With the far tier only stations in cells not wholly beyond the far range have their own links.
    const bool far = far_ && cells_.usable();
    const double radius = far ? std::min(cutoff_, farRange_ + cells_.size() * std::sqrt(2.0)) : cutoff_;
    // The far cells' vehicles (~40 % of the radius's) are dropped as the grid meets them, by
    // index (read in the grid's order), before they cost a candidate and a read by slot;
    // classify() would drop exactly these.
    const double fromX = stations_.x[s];
    const double fromY = stations_.y[s];
    // Written without a branch on the answer (near and far vehicles come mixed, by index): each
    // visited vehicle is stored and the end moves on only for a kept one.
    NearScratch& scratch = nearScratch();
    std::vector<Slot>& kept = scratch.kept;
    if (far) cells_.fillBeyond(fromX, fromY, radius, farRange_, scratch.table);
    const FarCells::BeyondTable& table = scratch.table;
    kept.resize(static_cast<std::size_t>(snapshot_.size()) + 1);
    Slot* const keptData = kept.data();
    std::size_t nKept = 0;
    const Slot* const slotOfIndex = stations_.slotOfIndex.data();
    const auto takeNear = [&](traffic::VehicleSnapshot::Index j) {
        const Slot r = slotOfIndex[j];
        keptData[nKept] = r;
        nKept += static_cast<std::size_t>(static_cast<int>(r >= 0) & static_cast<int>(r != s) &
                                          static_cast<int>(!cells_.beyondIndex(static_cast<std::size_t>(j), table)));
    };
    const auto visitGrid = [&](const auto& visit) {
        if (index) {
            grid_.forEachWithin(*index, radius, visit);
        } else if (fixedSelf) {
            grid_.forEachAround(fromX, fromY, radius, visit);
        }
    };
    if (far) {
        visitGrid(takeNear);
    } else {
        visitGrid(take);
    }
    if (far) candidates.assign(keptData, keptData + nKept);
    near.farTested = far ? candidates.size() : 0;
    if ((index || fixedSelf) && !fixed.empty()) {
        fixed.forEachWithin({stations_.x[s], stations_.y[s]}, cutoff_, fixedSelf, [&](FixedStations::Index k, double) {
            const auto it = stations_.slotOf.find(fixed.ids()[k]);
            if (it != stations_.slotOf.end() && stations_.present[it->second]) candidates.push_back(it->second);
        });
    }
    // The buildings wait for the sender's frame (applyObstacles): the batch guesses the step's
    // senders from the last step's, and with CAMs (1 to 10 Hz) half its guesses do not send.
    near.obstaclesPending = obstacles_ && obstacles_->size() > 0;
    if (!near.obstaclesPending) classify(s);
}

void LinkBudget::applyObstacles(Slot s, kernel::ParallelFor& pool) {
    // Within the step the snapshot's positions are those the neighbourhood was made from. A pair
    // whose two stations send in one step is walked once: the loss is the same both ways.
    Neighbourhood& near = near_[s];
    if (obstacleStep_ != step_) {
        obstacleStep_ = step_;
        obstacleDb_.newStep();
    }
    near.obstacleDb.resize(near.candidates.size());
    obstacleTodo_.clear();
    for (std::size_t k = 0; k < near.candidates.size(); ++k) {
        if (const double* loss = obstacleDb_.find(s, near.candidates[k])) {
            near.obstacleDb[k] = *loss;
        } else {
            obstacleTodo_.push_back(k);
        }
    }
    const Eigen::Vector2d from(stations_.x[s], stations_.y[s]);
    // With tiers, a link is skipped once its mean power is below skipBelow, whatever else it
    // crosses: its walk stops two walls past that (each wall only lowers it; two keep a wall's
    // worth of margin over rounding). classify() skips it exactly as with the whole walk.
    const double wallDb = obstacles_->perWallDb();
    const double skipBelow = settings_.interferenceFloorDbm - floorMarginDb_;
    const bool stop = settings_.linkTiers && wallDb > 0;
    pool.run(
        obstacleTodo_.size(),
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const std::size_t k = obstacleTodo_[i];
                const Slot r = near.candidates[k];
                const Eigen::Vector2d to(stations_.x[r], stations_.y[r]);
                int stopAt = Obstacles::kNoStop;
                if (stop) {
                    const double headroom = settings_.powerDbm - pathLoss_->lossDb((to - from).norm()) - skipBelow;
                    stopAt = static_cast<int>(std::clamp(std::floor(headroom / wallDb) + 2, 1.0, 1e6));
                }
                near.obstacleDb[k] = obstacles_->lossDb(from, to, stopAt);
            }
        },
        kObstacleLinksPerChunk);
    for (const std::size_t k : obstacleTodo_) obstacleDb_.add(s, near.candidates[k], near.obstacleDb[k]);
    classify(s);
    near.obstaclesPending = false;
}

namespace {
/// classify()'s per-link columns, one set per thread (a neighbourhood is classified on one).
struct ClassifyScratch {
    StepLinks::Column<std::uint32_t> candidate;  // index into the candidates
    StepLinks::Column<double> distance, lossDb;
    struct FarCell {
        FarCells::Cell cell;
        std::uint32_t occupants;
    };
    std::vector<FarCell> far;
};
/// This thread's columns. Not inlined: GCC re-derives an inlined thread_local's address at each
/// use (a __tls_get_addr per link).
[[gnu::noinline]] ClassifyScratch& classifyScratch() {
    static thread_local ClassifyScratch scratch;
    return scratch;
}
}  // namespace

void LinkBudget::classify(Slot s) {
    Neighbourhood& near = near_[s];
    const std::vector<Slot>& candidates = near.candidates;
    // A frame still on the air keeps the last step's links: a fresh set then, else this one anew.
    if (!near.links || near.links.use_count() > 1) near.links = std::make_shared<StepLinks>();
    StepLinks& step = *near.links;
    step.clear();
    near.full.clear();
    near.fullKey.clear();
    near.fullMeanDbm.clear();
    near.skipped = 0;
    const double fromX = stations_.x[s];
    const double fromY = stations_.y[s];
    const bool obstacles = obstacles_ && obstacles_->size() > 0;
    const bool tiers = settings_.linkTiers;
    // Tiers: below the floor by the cutoff's margin (buildings can put a link there), or below
    // the sensing threshold by the tier margin with its mean power below it too (so it can never
    // be detected).
    const double skipBelow = settings_.interferenceFloorDbm - floorMarginDb_;
    const double fullFrom = std::min(settings_.sensingDbm - settings_.tierMarginDb, settings_.sensingDbm - meanGainDb_);
    const bool far = far_ && cells_.usable();
    // In passes over columns (the links' distances, then their path loss in one call) rather than
    // link by link: the square roots go two at a time and the law is one virtual call, not one a
    // link. The values are those of the link-by-link form: the same operations on each.
    ClassifyScratch& columns = classifyScratch();
    columns.candidate.resize(candidates.size());
    columns.distance.resize(candidates.size());
    std::uint32_t* const keptCandidate = columns.candidate.data();
    double* const squared = columns.distance.data();
    const double* const x = stations_.x.data();
    const double* const y = stations_.y.data();
    std::size_t n = 0;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
        const Slot r = candidates[c];
        // In a far cell (below); the grid's candidates were tested as it met them.
        if (far && c >= near.farTested && cells_.beyond(r, fromX, fromY, farRange_)) continue;
        const double dx = x[r] - fromX;
        const double dy = y[r] - fromY;
        keptCandidate[n] = static_cast<std::uint32_t>(c);
        squared[n] = dx * dx + dy * dy;  // squared until the pass below
        ++n;
    }
    columns.candidate.resize(n);
    columns.distance.resize(n);
    Eigen::Map<Eigen::ArrayXd> distances(columns.distance.data(), static_cast<Eigen::Index>(n));
    distances = distances.sqrt();
    columns.lossDb.resize(n);
    pathLoss_->lossesDb(columns.distance, columns.lossDb);
    // The step's columns sized for every link and cut to what was kept: written through plain
    // pointers, not a push_back (its end pointer reloaded and stored per link and column).
    step.resizeLinks(n);
    near.resizeFull(n);
    Slot* const receivers = step.receivers.data();
    double* const distanceOut = step.distance.data();
    std::uint32_t* const bins = step.bin.data();
    std::uint8_t* const tier = step.tier.data();
    StepLinks::Units* const units = step.units.data();
    std::uint32_t* const full = near.full.data();
    std::uint64_t* const fullKey = near.fullKey.data();
    double* const fullMeanDbm = near.fullMeanDbm.data();
    std::size_t kept = 0;
    std::size_t drawn = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t c = columns.candidate[k];
        const Slot r = candidates[c];
        const double distance = columns.distance[k];
        double mean = settings_.powerDbm - columns.lossDb[k];
        if (obstacles) mean -= near.obstacleDb[c];
        if (tiers && mean < skipBelow) {
            ++near.skipped;
            continue;
        }
        receivers[kept] = r;
        distanceOut[kept] = distance;
        bins[kept] = static_cast<std::uint32_t>(distance / kDistanceBin);
        if (tiers && mean < fullFrom) {
            const double mw = dbToLinear(mean + meanGainDb_);
            tier[kept] = mw >= floorMw_ ? StepLinks::kInterference : StepLinks::kBelowFloor;
            units[kept] = Reception::unitsOf(mw);
        } else {
            tier[kept] = StepLinks::kDrawn;
            units[kept] = 0;
            full[drawn] = static_cast<std::uint32_t>(kept);
            fullKey[drawn] = stations_.keys[r];
            fullMeanDbm[drawn] = mean;
            ++drawn;
        }
        ++kept;
    }
    step.resizeLinks(kept);
    near.resizeFull(drawn);
    if (!far) return;
    // The far tier: a cell wholly beyond the far range is one link for its occupants, the mean power
    // at its centre (within the cutoff).
    columns.far.clear();
    columns.distance.clear();
    cells_.forEachOccupied(
        fromX, fromY, cutoff_ + cells_.size(),
        [&](FarCells::Cell cell, std::uint32_t occupants, double x, double y, std::int32_t cx, std::int32_t cy) {
            if (!cells_.cellBeyond(cx, cy, fromX, fromY, farRange_)) return;
            const double distance = std::hypot(x - fromX, y - fromY);
            if (distance > cutoff_) return;
            columns.far.push_back({cell, occupants});
            columns.distance.push_back(distance);
        });
    columns.lossDb.resize(columns.far.size());
    pathLoss_->lossesDb(columns.distance, columns.lossDb);
    for (std::size_t k = 0; k < columns.far.size(); ++k) {
        const double mean = settings_.powerDbm - columns.lossDb[k];
        if (mean < skipBelow) {
            near.skipped += columns.far[k].occupants;
            continue;
        }
        const double mw = dbToLinear(mean + meanGainDb_);
        step.farCell.push_back(columns.far[k].cell);
        step.farUnits.push_back(mw >= floorMw_ ? Reception::unitsOf(mw) : 0);
        step.farOccupants.push_back(columns.far[k].occupants);
        step.farBin.push_back(static_cast<std::uint32_t>(columns.distance[k] / kDistanceBin));
    }
}

}  // namespace sbsim::radio
