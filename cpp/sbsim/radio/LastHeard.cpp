#include "sbsim/radio/LastHeard.h"

#include <algorithm>
#include <cstring>

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
    if (const std::size_t e = findLate(station); e != kNotLate) {
        const auto before = kernel::SimTime::fromNanoseconds(lateNs_[e]);
        lateNs_[e] = now.raw();
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
    if (pending_ != nullptr && since.raw() <= pendingNs_ && split(stations)) {
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

namespace {
/// Newcomers fewer than a table's stations by this factor are kept aside (late_) first.
constexpr std::size_t kFewNewcomers = 16;
/// How many of `a` and `b` (n each) are equal from the start: eight at a time while the runs are
/// long (a chunk without an early exit, vectorised), then one at a time.
std::size_t sameRun(const LastHeard::Index* a, const LastHeard::Index* b, std::size_t n) {
    std::size_t k = 0;
    for (; k + 8 <= n; k += 8) {
        LastHeard::Index diff = 0;
        for (std::size_t d = 0; d < 8; ++d) diff |= a[k + d] ^ b[k + d];
        if (diff != 0) break;
    }
    while (k < n && a[k] == b[k]) ++k;
    return k;
}
}  // namespace

bool LastHeard::compare(std::span<const Index> last, std::span<const Index> next) {
    expectFrom_.reset();
    expectTo_.reset();
    nextFew_ = differ(last, next, nextGone_, nextCome_);
    // Nothing gone or come with every station matched in order: the same list.
    return nextFew_ && nextGone_.empty() && nextCome_.empty();
}

void LastHeard::expect(List from, List to) {
    expectFrom_ = std::move(from);
    expectTo_ = std::move(to);
}

bool LastHeard::split(const List& stations) {
    if (expectTo_ != nullptr && expectTo_ == stations && expectFrom_ == pending_) {
        // Both lists are held (by the hint and here), so the same pointers are the same contents.
        expectFrom_.reset();
        expectTo_.reset();
        gone_.swap(nextGone_);
        come_.swap(nextCome_);
        return nextFew_;
    }
    return differ(*pending_, *stations, gone_, come_);
}

bool LastHeard::differ(std::span<const Index> held, std::span<const Index> stations, std::vector<Index>& gone,
                       std::vector<Index>& come) {
    // Both lists come in a medium's order, which keeps the relative order of the stations that
    // stay: matched in step, a mismatch resolved by a short look ahead on either side. Any
    // matching is correct (a station matched only as gone and come is walked); a poor one costs.
    constexpr std::size_t kAhead = 8;
    const std::size_t limit = stations.size() / 4 + 16;
    gone.clear();
    come.clear();
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < held.size() && j < stations.size()) {
        if (held[i] == stations[j]) {
            const std::size_t same = 1 + sameRun(held.data() + i + 1, stations.data() + j + 1,
                                                 std::min(held.size() - i, stations.size() - j) - 1);
            i += same;
            j += same;
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
            gone.insert(gone.end(), held.begin() + static_cast<std::ptrdiff_t>(i),
                        held.begin() + static_cast<std::ptrdiff_t>(i + goneRun));
            i += goneRun;
        } else if (comeRun != 0) {
            come.insert(come.end(), stations.begin() + static_cast<std::ptrdiff_t>(j),
                        stations.begin() + static_cast<std::ptrdiff_t>(j + comeRun));
            j += comeRun;
        } else {
            gone.push_back(held[i++]);
            come.push_back(stations[j++]);
        }
        if (gone.size() + come.size() > limit) return false;
    }
    gone.insert(gone.end(), held.begin() + static_cast<std::ptrdiff_t>(i), held.end());
    come.insert(come.end(), stations.begin() + static_cast<std::ptrdiff_t>(j), stations.end());
    return gone.size() + come.size() <= limit;
}

void LastHeard::write(std::span<const Index> stations, kernel::SimTime::rep ns) {
    std::size_t at = 0;
    Index last = 0;
    for (const Index station : stations) {
        if (station < last) at = 0;
        last = station;
        at = seek(at, station);
        if (at < stations_.size() && stations_[at] == station) {
            heardNs_[at++] = ns;
        } else if (const std::size_t e = findLate(station); e != kNotLate) {
            lateNs_[e] = ns;
        }
    }
}

std::size_t LastHeard::findLate(Index station) const {
    const auto at = std::lower_bound(late_.begin(), late_.end(), station);
    return at != late_.end() && *at == station ? static_cast<std::size_t>(at - late_.begin()) : kNotLate;
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
    expectFrom_.reset();
    expectTo_.reset();
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
        } else if (const std::size_t e = late_.empty() ? kNotLate : findLate(station); e != kNotLate) {
            if (lateNs_[e] < since.raw()) unknown.push_back(station);
            lateNs_[e] = now.raw();
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
    std::size_t old = stations_.size();
    std::size_t add = newcomers_.size();
    if (add * kFewNewcomers > old) {
        // Many (a table filling): merged from the back, in place, a comparison per station moved.
        stations_.resize(old + add);
        heardNs_.resize(old + add);
        Index* const stations = stations_.data();
        kernel::SimTime::rep* const heard = heardNs_.data();
        for (std::size_t out = old + add; add > 0;) {
            --out;
            if (old > 0 && stations[old - 1] > newcomers_[add - 1]) {
                --old;
                stations[out] = stations[old];
                heard[out] = heard[old];
            } else {
                --add;
                stations[out] = newcomers_[add];
                heard[out] = now.raw();
            }
        }
        return;
    }
    // A few among many (a sender's next step): kept aside in the small sorted late_ list, so
    // the table's arrays move once per kLateMerge newcomers, not once per frame that has some.
    for (const Index station : newcomers_) {
        const auto at = std::upper_bound(late_.begin(), late_.end(), station);
        const auto k = at - late_.begin();
        late_.insert(at, station);
        lateNs_.insert(lateNs_.begin() + k, now.raw());
    }
    if (late_.size() > kLateMerge) mergeLate();
}

void LastHeard::mergeLate() {
    if (late_.empty()) return;
    const std::size_t old = stations_.size();
    stations_.resize(old + late_.size());
    heardNs_.resize(old + late_.size());
    Index* const stations = stations_.data();
    kernel::SimTime::rep* const heard = heardNs_.data();
    // Each late station's place found by a search, the stations above it moved as one block.
    std::size_t end = old;  // stations_[0, end) are not moved yet
    for (std::size_t k = late_.size(); k > 0; --k) {
        const Index station = late_[k - 1];
        // None is in the arrays, so none equals a station held: it goes after those below it.
        const std::size_t at = static_cast<std::size_t>(std::upper_bound(stations, stations + end, station) - stations);
        // The k late stations up to this one come before stations_[at, end): they move by k.
        std::memmove(stations + at + k, stations + at, (end - at) * sizeof(Index));
        std::memmove(heard + at + k, heard + at, (end - at) * sizeof(kernel::SimTime::rep));
        stations[at + k - 1] = station;
        heard[at + k - 1] = lateNs_[k - 1];
        end = at;
    }
    late_.clear();
    lateNs_.clear();
}

void LastHeard::forgetBefore(kernel::SimTime before) {
    settle();  // and a sender gone for good keeps no list
    mergeLate();
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
        std::vector<Index>().swap(nextGone_);
        std::vector<Index>().swap(nextCome_);
        std::vector<Index>().swap(late_);
        std::vector<kernel::SimTime::rep>().swap(lateNs_);
    }
}

}  // namespace sbsim::radio
