#include "sbsim/storyboard/BoardFeed.h"

namespace sbsim::storyboard {

BoardFeed::BoardFeed(kernel::Module& sumo, const traffic::VehicleSnapshot& snapshot, Storyboard& board,
                     std::optional<traffic::EquippedView> view)
    : snapshot_(snapshot), board_(board), view_(std::move(view)) {
    sumo.subscribe(traffic::SumoBridge::arrivedSignal, *this);
    sumo.subscribe(traffic::SumoBridge::stepSignal, *this);
}

void BoardFeed::receiveSignal(kernel::Module&, kernel::SignalId id, std::string_view value) {
    if (id == traffic::SumoBridge::arrivedSignal) leftSinceStep_.emplace_back(value);
}

void BoardFeed::receiveSignal(kernel::Module&, kernel::SignalId id, const kernel::Object&) {
    if (id != traffic::SumoBridge::stepSignal) return;
    if (!view_) {
        board_.update(snapshot_, std::move(leftSinceStep_));
    } else {
        // Unequipped vehicles are not there for the stories: never an ego, never a neighbour.
        view_->keepEquipped(leftSinceStep_);
        board_.update(view_->of(snapshot_), std::move(leftSinceStep_));
    }
    leftSinceStep_.clear();
}

}  // namespace sbsim::storyboard
