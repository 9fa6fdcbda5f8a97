#pragma once

#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic {

/// The traffic as only the V2X-equipped vehicles see it (--storyboard-equipped-only): a step's
/// snapshot without the unequipped vehicles, never an ego, never a neighbour.
class SBSIM_API EquippedView {
public:
    explicit EquippedView(Penetration penetration) : penetration_(penetration) {}

    /// The equipped vehicles of `snapshot`, in its order; valid until the next call.
    const VehicleSnapshot& of(const VehicleSnapshot& snapshot);
    /// Drops the unequipped vehicles from `ids`.
    void keepEquipped(std::vector<std::string>& ids) const;

private:
    Penetration penetration_;
    VehicleSnapshot view_;
    std::vector<VehicleSnapshot::Index> kept_;
};

}  // namespace sbsim::traffic
