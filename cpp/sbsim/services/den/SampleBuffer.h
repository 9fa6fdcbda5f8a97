#pragma once

#include <deque>
#include <numeric>

#include "sbsim/kernel/SimTime.h"

namespace sbsim::services {

/// Artery's sample buffer for the DEN triggers: a value sampled at most every `interval`, kept
/// for `duration` (newest first). full() when it holds duration / interval samples.
class SampleBuffer {
public:
    struct Sample {
        kernel::SimTime time;
        double value = 0;
    };

    SampleBuffer(kernel::SimTime duration, kernel::SimTime interval) : duration_(duration), interval_(interval) {}

    /// Takes `value` at `now` if an interval passed since the last sample; drops samples older
    /// than the duration.
    void feed(double value, kernel::SimTime now) {
        if (!samples_.empty() && now - samples_.front().time < interval_) return;
        samples_.push_front({now, value});
        while (!samples_.empty() && now - samples_.back().time >= duration_) samples_.pop_back();
    }
    const std::deque<Sample>& samples() const { return samples_; }  ///< newest first
    bool full() const { return static_cast<kernel::SimTime::rep>(samples_.size()) >= duration_ / interval_; }
    /// The samples taken at or after `since`, newest first.
    std::deque<Sample> notBefore(kernel::SimTime since) const {
        std::deque<Sample> out;
        for (const Sample& s : samples_) {
            if (s.time < since) break;
            out.push_back(s);
        }
        return out;
    }
    /// Time from the oldest to the newest of `samples`.
    static kernel::SimTime span(const std::deque<Sample>& samples) {
        return samples.empty() ? kernel::SimTime::zero() : samples.front().time - samples.back().time;
    }
    static double average(const std::deque<Sample>& samples) {
        if (samples.empty()) return 0;
        return std::accumulate(samples.begin(), samples.end(), 0.0,
                               [](double sum, const Sample& s) { return sum + s.value; }) /
               static_cast<double>(samples.size());
    }

private:
    kernel::SimTime duration_;
    kernel::SimTime interval_;
    std::deque<Sample> samples_;
};

}  // namespace sbsim::services
