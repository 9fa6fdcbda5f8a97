#include "sbsim/traffic/EquippedView.h"

namespace sbsim::traffic {

const VehicleSnapshot& EquippedView::of(const VehicleSnapshot& snapshot) {
    kept_.clear();
    for (VehicleSnapshot::Index i = 0; i < snapshot.size(); ++i) {
        if (penetration_.equipped(snapshot.ids()[i])) kept_.push_back(i);
    }
    view_.assignSubset(snapshot, kept_);
    return view_;
}

void EquippedView::keepEquipped(std::vector<std::string>& ids) const {
    std::erase_if(ids, [&](const std::string& id) { return !penetration_.equipped(id); });
}

}  // namespace sbsim::traffic
