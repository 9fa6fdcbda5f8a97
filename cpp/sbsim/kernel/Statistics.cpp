#include "sbsim/kernel/Statistics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbsim::kernel {

namespace {

/// Whether `s` is well-formed UTF-8 (no overlong forms, surrogates or code points past U+10FFFF):
/// the names end up in the summary's JSON and the Parquet file's strings, which take nothing else.
bool isUtf8(std::string_view s) {
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        const std::size_t n = c < 0x80                 ? 1
                              : c >= 0xc2 && c <= 0xdf ? 2
                              : c >= 0xe0 && c <= 0xef ? 3
                              : c >= 0xf0 && c <= 0xf4 ? 4
                                                       : 0;
        if (n == 0 || i + n > s.size()) return false;
        for (std::size_t k = 1; k < n; ++k) {
            if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
        }
        const auto second = n > 1 ? static_cast<unsigned char>(s[i + 1]) : 0;
        if ((c == 0xe0 && second < 0xa0) || (c == 0xed && second > 0x9f) || (c == 0xf0 && second < 0x90) ||
            (c == 0xf4 && second > 0x8f)) {
            return false;
        }
        i += n;
    }
    return true;
}

}  // namespace

void Statistics::record(std::string_view vehicle, std::string_view source, std::string_view name, SimTime time,
                        double value) {
    if (name.empty()) throw std::invalid_argument("a statistic needs a name");
    for (const auto& [what, text] : {std::pair{"name", name}, {"vehicle", vehicle}, {"source", source}}) {
        if (!isUtf8(text)) throw std::invalid_argument(fmt::format("a statistic's {} must be UTF-8 text", what));
    }
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
