#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::radio {

/// ETSI TS 102 687 reactive decentralized congestion control, with the semantics of Vanetza's
/// implementation: every 100 ms the channel busy ratio is smoothed (0.5 old + 0.5 new) and kept;
/// the state goes up when the smallest smoothed load of the last second (10 samples) reaches a
/// higher state's threshold and down when the largest of the last 5 s (50 samples) falls below the
/// current one. Relaxed below 0.19 (60 ms between transmissions), Active 1–5 up to 0.27, 0.35,
/// 0.43, 0.51, 0.59 (100, 180, 260, 340, 420 ms), Restrictive at or above 0.59 (460 ms).
class SBSIM_API DccStateMachine {
public:
    enum class State { Relaxed, Active, Restrictive };
    static constexpr kernel::SimTime kSampling = kernel::SimTime::fromMilliseconds(100);

    /// Feeds one 100 ms channel busy ratio sample.
    void update(double channelBusyRatio);

    State state() const { return state_; }
    /// 0 to 4 within Active (Active 1 to 5).
    std::size_t activeSubstate() const { return substate_; }
    /// "relaxed", "active1" … "active5" or "restrictive" (the message trace's dcc lines).
    std::string_view name() const;
    /// The least time between two transmissions the state allows.
    kernel::SimTime transmissionInterval() const;
    double smoothedLoad() const { return smoothed_; }
    double minLoad() const;  ///< over the last second
    double maxLoad() const;  ///< over the last 5 s

private:
    static constexpr std::size_t kSamplesUp = 10;
    static constexpr std::size_t kSamplesDown = 50;
    void chooseActiveSubstate();

    State state_ = State::Relaxed;
    std::size_t substate_ = 0;
    double smoothed_ = 0;
    std::array<double, kSamplesDown> history_{};  // ring, newest at (next_ - 1)
    std::size_t next_ = 0;
    std::size_t filled_ = 0;
};

}  // namespace sbsim::radio
