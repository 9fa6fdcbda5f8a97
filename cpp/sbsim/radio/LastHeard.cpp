#include "sbsim/radio/LastHeard.h"

#include <algorithm>

#include "sbsim/radio/CounterRandom.h"

namespace sbsim::radio {

std::optional<kernel::SimTime> LastHeard::hear(std::uint64_t station, kernel::SimTime now) {
    if (2 * (used_ + 1) > table_.size()) rebuild(std::max<std::size_t>(16, 2 * table_.size()));
    const std::size_t mask = table_.size() - 1;
    std::size_t at = CounterRandom::mix(station) & mask;
    while (table_[at].heardNs != kFree && table_[at].key != station) at = (at + 1) & mask;
    Entry& e = table_[at];
    std::optional<kernel::SimTime> before;
    if (e.heardNs == kFree) {
        e.key = station;
        ++used_;
    } else {
        before = kernel::SimTime::fromNanoseconds(e.heardNs);
    }
    e.heardNs = now.raw();
    return before;
}

void LastHeard::forgetBefore(kernel::SimTime before) {
    std::size_t kept = 0;
    for (Entry& e : table_) {
        if (e.heardNs == kFree) continue;
        if (e.heardNs < before.raw()) {
            e.heardNs = kFree;
        } else {
            ++kept;
        }
    }
    if (kept == used_) return;
    used_ = kept;
    if (used_ == 0) {
        std::vector<Entry>().swap(table_);  // a station gone for good holds no table
        return;
    }
    // Linear probing cannot just empty slots (a probe would stop early): laid out afresh.
    std::size_t slots = 16;
    while (slots < 2 * used_) slots *= 2;
    rebuild(slots);
}

void LastHeard::rebuild(std::size_t slots) {
    std::vector<Entry> old(slots);
    old.swap(table_);
    const std::size_t mask = slots - 1;
    for (const Entry& e : old) {
        if (e.heardNs == kFree) continue;
        std::size_t at = CounterRandom::mix(e.key) & mask;
        while (table_[at].heardNs != kFree) at = (at + 1) & mask;
        table_[at] = e;
    }
}

}  // namespace sbsim::radio
