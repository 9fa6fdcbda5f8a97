#pragma once

#include "sbsim/services/Service.h"

namespace sbsim::services {

/// An emergency vehicle's service: once the storyboard switches its siren on (a SignalEffect with
/// cause "siren on"), it broadcasts a ClearLaneMessage with its road and lane on every trigger.
/// Parameter: `cause` (default "siren on").
class PoliceService : public Service {
public:
    void initialize() override;
    void receiveSignal(const traffic::StoryboardSignal& signal) override;
    void trigger() override;

    bool sirenOn() const { return sirenOn_; }

private:
    std::string cause_;
    bool sirenOn_ = false;
};

}  // namespace sbsim::services
