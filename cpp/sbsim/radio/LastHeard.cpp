#include "sbsim/radio/LastHeard.h"

#include <algorithm>

namespace sbsim::radio {

std::size_t LastHeard::seek(std::size_t from, Index station) const {
    const std::size_t n = stations_.size();
    // The next receiver is usually a few places on (the stations heard lately but not now):
    // a short scan, then a galloping search so a gap costs its logarithm.
    for (std::size_t end = std::min(n, from + 8); from < end; ++from) {
        if (stations_[from] >= station) return from;
    }
    std::size_t step = 8;
    std::size_t hi = from;
    while (hi < n && stations_[hi] < station) {
        from = hi + 1;
        hi += step;
        step *= 2;
    }
    const auto first = stations_.begin();
    return static_cast<std::size_t>(std::lower_bound(first + static_cast<std::ptrdiff_t>(from),
                                                     first + static_cast<std::ptrdiff_t>(std::min(hi, n)), station) -
                                    first);
}

std::optional<kernel::SimTime> LastHeard::hear(Index station, kernel::SimTime now) {
    settle();
    const auto at = std::lower_bound(stations_.begin(), stations_.end(), station);
    const auto k = at - stations_.begin();
    if (at != stations_.end() && *at == station) {
        const auto before = kernel::SimTime::fromNanoseconds(heardNs_[static_cast<std::size_t>(k)]);
        heardNs_[static_cast<std::size_t>(k)] = now.raw();
        return before;
    }
    stations_.insert(at, station);
    heardNs_.insert(heardNs_.begin() + k, now.raw());
    return std::nullopt;
}

void LastHeard::hearAll(std::span<const Index> stations, kernel::SimTime now, kernel::SimTime since,
                        std::vector<Index>& unknown) {
    settle();
    walk(stations, now, since, unknown);
}

void LastHeard::hearList(List stations, kernel::SimTime now, kernel::SimTime since, std::vector<Index>& unknown) {
    // Every station of the list was last heard at pendingNs_ (anything else touching the arrays
    // writes the notes first and drops the list): none is unknown unless that is before `since`,
    // and a walk would only write `now`.
    if (stations == pending_ && since.raw() <= pendingNs_) {
        pendingNs_ = now.raw();
        pendingDirty_ = true;
        return;
    }
    if (pending_ != nullptr && since.raw() <= pendingNs_ && differ(*stations)) {
        // Kept stations are known and note `now` with the new list; gone ones get the held
        // list's time first, so a station matched as gone and come reads it as a walk would.
        if (pendingDirty_) write(gone_, pendingNs_);
        walk(come_, now, since, unknown);
        ++differences_;
        pending_ = std::move(stations);
        pendingNs_ = now.raw();
        pendingDirty_ = true;
        return;
    }
    flush();
    walk(*stations, now, since, unknown);
    pending_ = std::move(stations);
    pendingNs_ = now.raw();
}

bool LastHeard::differ(std::span<const Index> stations) {
    // Both lists come in a medium's order, which keeps the relative order of the stations that
    // stay: matched in step, a mismatch resolved by a short look ahead on either side. Any
    // matching is correct (a station matched only as gone and come is walked); a poor one costs.
    constexpr std::size_t kAhead = 8;
    const std::span<const Index> held(*pending_);
    const std::size_t limit = stations.size() / 4 + 16;
    gone_.clear();
    come_.clear();
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < held.size() && j < stations.size()) {
        if (held[i] == stations[j]) {
            ++i;
            ++j;
            continue;
        }
        std::size_t goneRun = 0;  // held[i, i + goneRun) gone, then held matches stations[j]
        for (std::size_t d = 1; d <= kAhead && i + d < held.size(); ++d) {
            if (held[i + d] == stations[j]) {
                goneRun = d;
                break;
            }
        }
        std::size_t comeRun = 0;  // stations[j, j + comeRun) come, then stations matches held[i]
        for (std::size_t d = 1; d <= kAhead && j + d < stations.size(); ++d) {
            if (stations[j + d] == held[i]) {
                comeRun = d;
                break;
            }
        }
        if (goneRun != 0 && (comeRun == 0 || goneRun <= comeRun)) {
            gone_.insert(gone_.end(), held.begin() + static_cast<std::ptrdiff_t>(i),
                         held.begin() + static_cast<std::ptrdiff_t>(i + goneRun));
            i += goneRun;
        } else if (comeRun != 0) {
            come_.insert(come_.end(), stations.begin() + static_cast<std::ptrdiff_t>(j),
                         stations.begin() + static_cast<std::ptrdiff_t>(j + comeRun));
            j += comeRun;
        } else {
            gone_.push_back(held[i++]);
            come_.push_back(stations[j++]);
        }
        if (gone_.size() + come_.size() > limit) return false;
    }
    gone_.insert(gone_.end(), held.begin() + static_cast<std::ptrdiff_t>(i), held.end());
    come_.insert(come_.end(), stations.begin() + static_cast<std::ptrdiff_t>(j), stations.end());
    return gone_.size() + come_.size() <= limit;
}

void LastHeard::write(std::span<const Index> stations, kernel::SimTime::rep ns) {
    std::size_t at = 0;
    Index last = 0;
    for (const Index station : stations) {
        if (station < last) at = 0;
        last = station;
        at = seek(at, station);
        if (at < stations_.size() && stations_[at] == station) heardNs_[at++] = ns;
    }
}

void LastHeard::flush() {
    if (!pendingDirty_) return;
    pendingDirty_ = false;
    // The list's stations are all in the arrays (its first walk added them): a walk that writes.
    write(*pending_, pendingNs_);
}

void LastHeard::settle() {
    flush();
    pending_.reset();
}

void LastHeard::walk(std::span<const Index> stations, kernel::SimTime now, kernel::SimTime since,
                     std::vector<Index>& unknown) {
    newcomers_.clear();
    std::size_t at = 0;
    Index last = 0;
    for (const Index station : stations) {
        if (station < last) at = 0;  // out of order: from the start again
        last = station;
        at = seek(at, station);
        if (at < stations_.size() && stations_[at] == station) {
            if (heardNs_[at] < since.raw()) unknown.push_back(station);
            heardNs_[at] = now.raw();
            ++at;
        } else {
            newcomers_.push_back(station);
            unknown.push_back(station);
        }
    }
    if (!newcomers_.empty()) addNewcomers(now);
}

void LastHeard::addNewcomers(kernel::SimTime now) {
    std::sort(newcomers_.begin(), newcomers_.end());
    newcomers_.erase(std::unique(newcomers_.begin(), newcomers_.end()), newcomers_.end());
    // Merged from the back, in place: each array moves once.
    std::size_t old = stations_.size();
    std::size_t add = newcomers_.size();
    stations_.resize(old + add);
    heardNs_.resize(old + add);
    for (std::size_t out = old + add; add > 0;) {
        --out;
        if (old > 0 && stations_[old - 1] > newcomers_[add - 1]) {
            --old;
            stations_[out] = stations_[old];
            heardNs_[out] = heardNs_[old];
        } else {
            --add;
            stations_[out] = newcomers_[add];
            heardNs_[out] = now.raw();
        }
    }
}

void LastHeard::forgetBefore(kernel::SimTime before) {
    settle();  // and a sender gone for good keeps no list
    std::size_t kept = 0;
    for (std::size_t k = 0; k < stations_.size(); ++k) {
        if (heardNs_[k] < before.raw()) continue;
        stations_[kept] = stations_[k];
        heardNs_[kept] = heardNs_[k];
        ++kept;
    }
    if (kept == stations_.size()) return;
    stations_.resize(kept);
    heardNs_.resize(kept);
    if (kept == 0 || kept < stations_.capacity() / 4) {
        // A station gone for good holds no table, one heard by fewer its smaller one.
        stations_.shrink_to_fit();
        heardNs_.shrink_to_fit();
        std::vector<Index>().swap(newcomers_);
        std::vector<Index>().swap(gone_);
        std::vector<Index>().swap(come_);
    }
}

}  // namespace sbsim::radio
