#pragma once

#include "sbsim/services/den/UseCase.h"

namespace sbsim::services {

/// Artery's TractionLoss: the storyboard signal "traction loss" makes the vehicle send a DENM
/// (cause 6 adverse weather: adhesion, sub-cause 0; relevance < 100 m, all directions; validity
/// 600 s; destination a 1,000 m circle; traffic class 1) repeated every 1 s for 300 s. Detection
/// is then blocked for 20 s (a signal meanwhile waits).
class TractionLoss : public UseCase {
public:
    static constexpr int kCause = 6;

    void initialize() override;
    void check() override;
    void handleSignal(const traffic::StoryboardSignal& signal) override;

private:
    bool pending_ = false;
};

}  // namespace sbsim::services
