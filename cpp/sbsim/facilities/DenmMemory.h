#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "sbsim/facilities/ActionId.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/facilities/DenmPhase.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::facilities {

/// A receiver's DENM memory: the events it was told of, by action id. A DENM with a newer
/// reference time than the one kept replaces it (a repetition, same reference time, changes
/// nothing); a termination DENM ends the event; an event expires at its detection time + validity.
class SBSIM_API DenmMemory {
public:
    struct Entry {
        DenmContent denm;
        kernel::SimTime receivedAt;    ///< of the version kept
        kernel::SimTime firstHeardAt;  ///< of the event's first DENM here
        kernel::SimTime lastHeardAt;   ///< of its latest DENM here, a repetition too
    };

    /// Takes in a DENM received at `now`; returns what happened to its event (New, Update,
    /// Terminate), or nothing for a repetition, an older version, an already expired DENM or the
    /// termination of an event not kept.
    std::optional<DenmPhase> received(const DenmContent& denm, kernel::SimTime now);
    /// Drops the events whose expiry is before `now`; returns them. Walks the events only when
    /// one can be due (earliestExpiry() before `now`): a trigger with nothing due costs a comparison.
    std::vector<Entry> dropExpired(kernel::SimTime now);
    /// At or before every kept event's expiry (SimTime::max() while none was kept since the last
    /// walk): a termination or an update to a later expiry leaves it early, which only costs a walk.
    kernel::SimTime earliestExpiry() const { return earliest_; }

    const std::map<ActionId, Entry>& entries() const { return entries_; }
    const Entry* find(const ActionId& action) const;
    std::size_t size() const { return entries_.size(); }
    /// Events with cause code `cause` not expired at `now`.
    std::size_t count(int cause, kernel::SimTime now) const;

private:
    std::map<ActionId, Entry> entries_;
    kernel::SimTime earliest_ = kernel::SimTime::max();
};

}  // namespace sbsim::facilities
