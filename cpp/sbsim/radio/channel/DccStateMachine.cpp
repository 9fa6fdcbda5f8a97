#include "sbsim/radio/channel/DccStateMachine.h"

#include <algorithm>
#include <limits>

namespace sbsim::radio {

namespace {
constexpr double kMinLoad = 0.19;  // below: Relaxed
constexpr double kMaxLoad = 0.59;  // at or above: Restrictive
constexpr std::array<double, 5> kActiveUpper{0.27, 0.35, 0.43, 0.51, 0.59};
constexpr std::array<int, 5> kActiveIntervalMs{100, 180, 260, 340, 420};
}  // namespace

void DccStateMachine::update(double channelBusyRatio) {
    smoothed_ = 0.5 * smoothed_ + 0.5 * channelBusyRatio;
    history_[next_] = smoothed_;
    next_ = (next_ + 1) % kSamplesDown;
    filled_ = std::min(filled_ + 1, kSamplesDown);

    switch (state_) {
        case State::Relaxed:
            if (minLoad() >= kMinLoad) {
                state_ = State::Active;
                chooseActiveSubstate();
            }
            break;
        case State::Restrictive:
            if (maxLoad() < kMaxLoad) {
                state_ = State::Active;
                chooseActiveSubstate();
            }
            break;
        case State::Active:
            if (maxLoad() < kMinLoad) {
                state_ = State::Relaxed;
            } else if (minLoad() >= kMaxLoad) {
                state_ = State::Restrictive;
            } else {
                chooseActiveSubstate();
            }
            break;
    }
}

void DccStateMachine::chooseActiveSubstate() {
    // The substate whose band holds the load; going up needs the whole last second above a
    // threshold, going down the whole last 5 s below it, so the larger of the two wins.
    const auto band = [](double load) {
        return static_cast<std::size_t>(std::upper_bound(kActiveUpper.begin(), kActiveUpper.end(), load) -
                                        kActiveUpper.begin());
    };
    substate_ = std::min<std::size_t>(kActiveUpper.size() - 1, std::max(band(minLoad()), band(maxLoad())));
}

double DccStateMachine::minLoad() const {
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < std::min(filled_, kSamplesUp); ++k)
        least = std::min(least, history_[(next_ + kSamplesDown - 1 - k) % kSamplesDown]);
    return filled_ == 0 ? 0.0 : least;
}

double DccStateMachine::maxLoad() const {
    double most = 0;
    for (std::size_t k = 0; k < filled_; ++k)
        most = std::max(most, history_[(next_ + kSamplesDown - 1 - k) % kSamplesDown]);
    return most;
}

kernel::SimTime DccStateMachine::transmissionInterval() const {
    switch (state_) {
        case State::Relaxed:
            return kernel::SimTime::fromMilliseconds(60);
        case State::Restrictive:
            return kernel::SimTime::fromMilliseconds(460);
        case State::Active:
            break;
    }
    return kernel::SimTime::fromMilliseconds(kActiveIntervalMs[substate_]);
}

std::string_view DccStateMachine::name() const {
    static constexpr std::string_view kActive[] = {"active1", "active2", "active3", "active4", "active5"};
    switch (state_) {
        case State::Relaxed:
            return "relaxed";
        case State::Active:
            return kActive[substate_];
        case State::Restrictive:
            break;
    }
    return "restrictive";
}

}  // namespace sbsim::radio
