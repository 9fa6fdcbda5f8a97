#pragma once

#include "sbsim/services/Service.h"

namespace sbsim::services {

/// Artery's highway-police PoliceService: an emergency vehicle that broadcasts a ClearLaneMessage
/// with its road and lane on every trigger, from its departure on.
class PoliceService : public Service {
public:
    void trigger() override;

protected:
    /// Whether it broadcasts now (always, here).
    virtual bool broadcasting() const { return true; }
};

/// Artery's PoliceServiceStoryboard: the same, once the storyboard switched the siren on (a
/// SignalEffect with cause "siren on" for this vehicle). Parameter: `cause` (default "siren on").
class PoliceServiceStoryboard : public PoliceService {
public:
    void initialize() override;
    void receiveSignal(const traffic::StoryboardSignal& signal) override;
    bool sirenOn() const { return sirenOn_; }

protected:
    bool broadcasting() const override { return sirenOn_; }

private:
    std::string cause_;
    bool sirenOn_ = false;
};

}  // namespace sbsim::services
