#pragma once

#include "sbsim/facilities/Denm.h"
#include "sbsim/services/den/UseCase.h"

namespace sbsim::services {

/// Artery's ImpactReductionContainerExchange: the storyboard signal "irc" makes the vehicle send
/// a request; a vehicle receiving a request answers with a response. Both: cause 97 collision
/// risk; relevance < 100 m, all directions; validity 2 s; a 100 m circle; repeated every 0.1 s for
/// 0.3 s; traffic class 0; with the impact-reduction container.
class ImpactReductionContainerExchange : public UseCase {
public:
    static constexpr int kCause = 97;

    void check() override;
    void handleSignal(const traffic::StoryboardSignal& signal) override;
    void indicate(const facilities::Denm& denm) override;

private:
    void transmit(facilities::ImpactReduction indication);
    bool pendingRequest_ = false;
};

}  // namespace sbsim::services
