#include "sbsim/kernel/StudyParameters.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>

namespace sbsim::kernel {

namespace {

bool validName(std::string_view name) {
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front()))) return false;
    for (const char c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.' && c != '-') return false;
    }
    return true;
}

}  // namespace

StudyParameters::Value StudyParameters::parse(std::string_view text) {
    if (text == "true") return true;
    if (text == "false") return false;
    const char* end = text.data() + text.size();
    std::int64_t whole = 0;
    if (auto [ptr, ec] = std::from_chars(text.data(), end, whole); ec == std::errc() && ptr == end && !text.empty()) {
        return whole;
    }
    double number = 0;
    if (auto [ptr, ec] = std::from_chars(text.data(), end, number);
        ec == std::errc() && ptr == end && !text.empty() && std::isfinite(number)) {
        return number;
    }
    return std::string(text);
}

std::string StudyParameters::format(const Value& value) {
    return std::visit(
        [](const auto& v) -> std::string {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, bool>) {
                return v ? "true" : "false";
            } else if constexpr (std::is_same_v<T, double>) {
                std::string out = fmt::format("{}", v);
                if (out.find_first_of(".eE") == std::string::npos) out += ".0";
                return out;
            } else {
                return fmt::format("{}", v);
            }
        },
        value);
}

void StudyParameters::add(std::string_view assignment) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string_view::npos) {
        throw StudyParameterError(fmt::format("expects NAME=VALUE, got '{}'", assignment));
    }
    const std::string name(assignment.substr(0, eq));
    if (!validName(name)) {
        throw StudyParameterError(fmt::format(
            "'{}' is not a parameter name (letters, digits, '_', '.', '-'; not starting with a digit)", name));
    }
    if (values_.count(name) != 0) throw StudyParameterError(fmt::format("'{}' is given twice", name));
    values_.emplace(name, parse(assignment.substr(eq + 1)));
}

std::optional<StudyParameters::Value> StudyParameters::get(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    read_.insert(name);
    return it->second;
}

std::vector<std::string> StudyParameters::unread() const {
    std::vector<std::string> out;
    for (const auto& [name, value] : values_) {
        if (read_.count(name) == 0) out.push_back(name);
    }
    return out;
}

}  // namespace sbsim::kernel
