#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::kernel {

/// The values a run's services and stories record, as OMNeT++ modules record scalars and vectors:
/// one row per value (vehicle, source, name, time, value), kept in columns, in the order recorded
/// (the simulation's order, so the same whatever the thread count), plus an aggregate per name.
/// One per run; record only from the simulation's thread (services and story scripts run there).
class SBSIM_API Statistics {
public:
    /// count, sum, min, max of one name's values over the run.
    struct Aggregate {
        std::size_t count = 0;
        double sum = 0;
        double min = 0;
        double max = 0;
        double mean() const { return count == 0 ? 0.0 : sum / static_cast<double>(count); }
    };

    /// Records `value` of `name` at `time`; `vehicle` is empty for a value of no vehicle, `source`
    /// the service type or story that recorded it. Throws std::invalid_argument for an empty name
    /// or a value that is not finite (a NaN would poison every aggregate of the name).
    void record(std::string_view vehicle, std::string_view source, std::string_view name, SimTime time, double value);

    std::size_t size() const { return values_.size(); }
    const std::vector<std::string>& vehicles() const { return vehicles_; }
    const std::vector<std::string>& sources() const { return sources_; }
    const std::vector<std::string>& names() const { return names_; }
    const std::vector<double>& times() const { return times_; }  ///< s
    const std::vector<double>& values() const { return values_; }
    /// Per name, sorted by name.
    const std::map<std::string, Aggregate, std::less<>>& aggregates() const { return aggregates_; }

private:
    std::vector<std::string> vehicles_;
    std::vector<std::string> sources_;
    std::vector<std::string> names_;
    std::vector<double> times_;
    std::vector<double> values_;
    std::map<std::string, Aggregate, std::less<>> aggregates_;
};

}  // namespace sbsim::kernel
