#pragma once

#include <compare>
#include <cstdint>
#include <limits>
#include <string>

#include "sbsim/kernel/Export.h"

namespace sbsim::kernel {

/// Simulation time as an exact integer count of nanoseconds (like OMNeT++'s simtime_t with a fixed
/// scale). SUMO works in milliseconds, so every SUMO step time is representable without drift,
/// and radio latencies well below a millisecond still fit. Range: about ±292 years.
class SBSIM_API SimTime {
public:
    using rep = std::int64_t;
    static constexpr rep kPerSecond = 1'000'000'000;

    constexpr SimTime() = default;

    static constexpr SimTime fromRaw(rep ns) { return SimTime(ns); }
    static constexpr SimTime fromNanoseconds(rep ns) { return SimTime(ns); }
    static constexpr SimTime fromMilliseconds(rep ms) { return SimTime(ms * 1'000'000); }
    /// Rounds to the nearest nanosecond, so 0.1 s becomes exactly 100'000'000 ns.
    static SimTime fromSeconds(double seconds);
    static constexpr SimTime zero() { return SimTime(0); }
    static constexpr SimTime max() { return SimTime(std::numeric_limits<rep>::max()); }

    constexpr rep raw() const { return ns_; }
    constexpr rep milliseconds() const { return ns_ / 1'000'000; }
    constexpr double seconds() const { return static_cast<double>(ns_) / kPerSecond; }
    /// Shortest decimal seconds that round-trips, e.g. "12.3" or "0.000001".
    std::string str() const;

    constexpr auto operator<=>(const SimTime&) const = default;

    // Checked: times come from scripts and files, and a wrapped sum would be a silent wrong time.
    constexpr SimTime operator+(SimTime o) const {
        rep sum = 0;
        if (__builtin_add_overflow(ns_, o.ns_, &sum)) throwOverflow();
        return SimTime(sum);
    }
    constexpr SimTime operator-(SimTime o) const {
        rep difference = 0;
        if (__builtin_sub_overflow(ns_, o.ns_, &difference)) throwOverflow();
        return SimTime(difference);
    }
    constexpr SimTime operator-() const { return SimTime(-ns_); }
    constexpr SimTime operator*(rep k) const { return SimTime(ns_ * k); }
    constexpr rep operator/(SimTime o) const { return ns_ / o.ns_; }
    constexpr SimTime operator%(SimTime o) const { return SimTime(ns_ % o.ns_); }
    constexpr SimTime& operator+=(SimTime o) { return *this = *this + o; }
    constexpr SimTime& operator-=(SimTime o) { return *this = *this - o; }

private:
    constexpr explicit SimTime(rep ns) : ns_(ns) {}
    [[noreturn]] static void throwOverflow();
    rep ns_ = 0;
};

}  // namespace sbsim::kernel
