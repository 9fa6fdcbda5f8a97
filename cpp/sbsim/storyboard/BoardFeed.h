#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Signal.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/traffic/EquippedView.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::storyboard {

/// Feeds a board from the SUMO bridge: after every step, the bridge's snapshot and the vehicles
/// that left since the last step, seen through an EquippedView with --storyboard-equipped-only.
class SBSIM_API BoardFeed : private kernel::Listener {
public:
    /// `sumo` emits traffic::SumoBridge's arrived and step signals (the bridge, or a stand-in);
    /// `snapshot` is the one it refreshes before each step signal.
    BoardFeed(kernel::Module& sumo, const traffic::VehicleSnapshot& snapshot, Storyboard& board,
              std::optional<traffic::EquippedView> view = std::nullopt);
    BoardFeed(const BoardFeed&) = delete;
    BoardFeed& operator=(const BoardFeed&) = delete;

private:
    void receiveSignal(kernel::Module& source, kernel::SignalId id, std::string_view value) override;
    void receiveSignal(kernel::Module& source, kernel::SignalId id, const kernel::Object& value) override;

    const traffic::VehicleSnapshot& snapshot_;
    Storyboard& board_;
    std::optional<traffic::EquippedView> view_;
    std::vector<std::string> leftSinceStep_;
};

}  // namespace sbsim::storyboard
