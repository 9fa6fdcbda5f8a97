#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::radio {

/// When each of a set of stations last heard something, by the station's index (StationIds):
/// two arrays sorted by index (indices, times), 12 bytes a station. A frame's receivers, which the
/// media find in an order close to their indices', are matched by one forward walk (hearAll), so
/// the tables of a full city (5,000 senders, ~1,000 stations each) are read sequentially where a
/// hash table's random probes cost a cache miss per reception (a third of the disc model's run).
///
/// A list that comes again (hearList: a medium's receivers of a step, shared by the sender's
/// frames of that step) is walked once: its repeats, which can find no station unknown, only note
/// their time, written out when another list comes, and before hear(), hearAll() or
/// forgetBefore() read the times. Another list that differs from the one held by a few stations
/// (the sender's receivers of the next step) walks only the difference: its stations kept were
/// heard at the held list's time, so they are known and only note the new one (as a repeat);
/// those gone write the held time, those come are walked. Answers are those of a walk per frame.
///
/// A medium that must compare the sender's next list with its last anyway (to share the last
/// again when equal) makes that comparison the split hearList() takes (compare(), then expect()
/// once the new list is shared), so the two lists are matched once, not twice.
class SBSIM_API LastHeard {
public:
    using Index = std::uint32_t;
    using List = std::shared_ptr<const std::vector<Index>>;

    /// Records that `station` heard at `now`; returns when it heard last before, if ever.
    std::optional<kernel::SimTime> hear(Index station, kernel::SimTime now);
    /// Records that each of `stations` (distinct) heard at `now`, walking them in their order
    /// (fastest when ascending; any order is correct), and appends to `unknown` those that had
    /// not heard since `since` (or never).
    void hearAll(std::span<const Index> stations, kernel::SimTime now, kernel::SimTime since,
                 std::vector<Index>& unknown);
    /// As hearAll() for `stations`, which must not change while it is held here (kept until
    /// another list comes or forgetBefore()): the same list again, when none of its stations can
    /// have been heard before `since`, costs no walk.
    void hearList(List stations, kernel::SimTime now, kernel::SimTime since, std::vector<Index>& unknown);
    /// Compares a sender's `next` list with its `last` as hearList() would split them; true when
    /// they are equal. The split is kept for expect().
    bool compare(std::span<const Index> last, std::span<const Index> next);
    /// `from` and `to` hold the lists compare() last compared (unchanged since): hearList(to), while
    /// `from` is the list held, takes compare()'s split instead of matching the lists again.
    void expect(List from, List to);
    /// Forgets the stations that last heard before `before`.
    void forgetBefore(kernel::SimTime before);
    /// Repeats of a list noted and not yet written (for tests).
    bool pending() const { return pendingDirty_; }
    /// Lists taken by their difference from the one held (for tests).
    std::size_t differences() const { return differences_; }
    std::size_t size() const { return stations_.size() + late_.size(); }

private:
    /// The first position at or after `from` whose station is not below `station`.
    std::size_t seek(std::size_t from, Index station) const;
    /// Adds `newcomers_` (heard at `now`, none known): merged into the sorted arrays when many,
    /// else kept aside in late_ until it holds more than kLateMerge.
    void addNewcomers(kernel::SimTime now);
    /// Merges late_ into the sorted arrays (block moves: each station of the arrays moves once).
    void mergeLate();
    /// The position of `station` in late_, or kNotLate.
    std::size_t findLate(Index station) const;
    /// Writes the times the repeats of `pending_` noted, so the arrays hold every reception.
    void flush();
    /// flush(), and the list dropped: the arrays are about to change otherwise.
    void settle();
    /// Splits `stations` against `held` into `gone` (held only) and `come` (new only, in their
    /// order), the rest matched in order; false when they differ by too many for this to pay.
    static bool differ(std::span<const Index> held, std::span<const Index> stations, std::vector<Index>& gone,
                       std::vector<Index>& come);
    /// differ() against `pending_` into gone_ and come_, or the split expect() named for this list.
    bool split(const List& stations);
    /// Writes `ns` as the time of each of `stations`, all in the arrays.
    void write(std::span<const Index> stations, kernel::SimTime::rep ns);
    /// hearAll()'s walk, on arrays that hold every reception.
    void walk(std::span<const Index> stations, kernel::SimTime now, kernel::SimTime since, std::vector<Index>& unknown);

    std::vector<Index> stations_;                // ascending
    std::vector<kernel::SimTime::rep> heardNs_;  // as stations_
    /// Stations new to the table lately, ascending, none in stations_, and when they heard: the
    /// arrays above take them once there are more than kLateMerge, so a sender's next step, which
    /// brings a few, moves no block of the arrays (a miss per cache line of a ~1,500-station table).
    std::vector<Index> late_;
    std::vector<kernel::SimTime::rep> lateNs_;
    static constexpr std::size_t kLateMerge = 64;
    static constexpr std::size_t kNotLate = static_cast<std::size_t>(-1);
    std::vector<Index> newcomers_;            // scratch of hearAll
    std::vector<Index> gone_, come_;          // scratch of hearList's difference
    std::vector<Index> nextGone_, nextCome_;  // compare()'s split
    bool nextFew_ = false;                    // compare()'s differ() answer
    List expectFrom_, expectTo_;              // the lists of nextGone_ and nextCome_ (expect)
    List pending_;                            // the last list walked or noted (hearList)
    kernel::SimTime::rep pendingNs_ = 0;      // when it was heard last: every station of it at or after
    bool pendingDirty_ = false;               // its stations' times in the arrays are older
    std::size_t differences_ = 0;
};

}  // namespace sbsim::radio
