#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace sbsim::traffic {

/// One domain of a vehicle's effects (a speed factor, a type, a colour): the most recently
/// activated active entry rules, and the value from before the first entry comes back when the
/// last one ends, in whatever order they end. It only decides; the EffectStack commands.
template <typename T>
class LatestWins {
public:
    using Token = std::uint64_t;

    std::optional<T> effective() const {
        if (entries_.empty()) return std::nullopt;
        return entries_.back().second;
    }
    bool contains(Token token) const {
        return std::any_of(entries_.begin(), entries_.end(), [token](const auto& e) { return e.first == token; });
    }
    bool empty() const { return entries_.empty(); }
    /// The value that comes back after the last entry (meaningful while not empty).
    const T& original() const { return original_; }
    /// Replaces it, when something else changed what the vehicle's own value is.
    void setOriginal(T value) { original_ = std::move(value); }

    /// Adds `value` for `token`. `original()` gives the live value; it is asked only when the domain
    /// was empty, and comes back at the end. Returns the value to command, if the vehicle's changes.
    template <typename Original>
    std::optional<T> push(Token token, T value, const Original& original) {
        const std::optional<T> before = effective();
        if (!before) original_ = original();
        entries_.emplace_back(token, std::move(value));
        return change(before);
    }
    /// Removes `token`'s entry, if here. Returns the value to command, if the vehicle's changes.
    std::optional<T> remove(Token token) {
        const auto it =
            std::find_if(entries_.begin(), entries_.end(), [token](const auto& e) { return e.first == token; });
        if (it == entries_.end()) return std::nullopt;
        const std::optional<T> before = effective();
        entries_.erase(it);
        return change(before);
    }

private:
    std::optional<T> change(const std::optional<T>& before) const {
        const std::optional<T> now = effective();
        if (now == before) return std::nullopt;
        return now ? *now : original_;
    }

    std::vector<std::pair<Token, T>> entries_;  // activation order
    T original_{};
};

}  // namespace sbsim::traffic
