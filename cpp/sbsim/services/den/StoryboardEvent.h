#pragma once

#include <optional>
#include <string>

#include "sbsim/facilities/ActionId.h"
#include "sbsim/services/den/UseCase.h"

namespace sbsim::services {

/// sbsim's storyboard-triggered event: when a story's SignalEffect sends `signal` to the vehicle,
/// it sends a DENM with the attributes' cause, sub-cause, relevance, validity and area, repeated
/// as asked; a signal `endSignal` (e.g. the SignalEffect's exit cause) ends the event: the
/// repetition stops and a cancellation DENM makes receivers drop it.
///
///     <usecase type="StoryboardEvent" signal="accident" endSignal="accident over" cause="2"
///              subcause="0" relevance="1000" validity="600" area="1000" interval="1" duration="600"/>
///
/// Defaults: cause 0 (unavailable), sub-cause 0, no relevance distance, validity 600 s, area 1,000 m,
/// interval 1 s, duration = validity; `signal` is required.
class StoryboardEvent : public UseCase {
public:
    void initialize() override;
    void check() override;
    void handleSignal(const traffic::StoryboardSignal& signal) override;

private:
    std::string signal_;
    std::optional<std::string> endSignal_;
    bool pending_ = false;
    std::optional<facilities::ActionId> event_;
};

}  // namespace sbsim::services
