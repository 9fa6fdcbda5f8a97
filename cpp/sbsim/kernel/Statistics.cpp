#include "sbsim/kernel/Statistics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbsim::kernel {

void Statistics::record(std::string_view vehicle, std::string_view source, std::string_view name, SimTime time,
                        double value) {
    if (name.empty()) throw std::invalid_argument("a statistic needs a name");
    if (!std::isfinite(value))
        throw std::invalid_argument(fmt::format("statistic '{}': {} is not finite", name, value));
    vehicles_.emplace_back(vehicle);
    sources_.emplace_back(source);
    names_.emplace_back(name);
    times_.push_back(time.seconds());
    values_.push_back(value);
    auto it = aggregates_.find(name);
    if (it == aggregates_.end()) {
        aggregates_.emplace(std::string(name), Aggregate{1, value, value, value});
        return;
    }
    Aggregate& a = it->second;
    ++a.count;
    a.sum += value;
    a.min = std::min(a.min, value);
    a.max = std::max(a.max, value);
}

}  // namespace sbsim::kernel
