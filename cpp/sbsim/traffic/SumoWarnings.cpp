#include "sbsim/traffic/SumoWarnings.h"

#include <algorithm>
#include <cctype>

namespace sbsim::traffic {

namespace {

constexpr std::string_view kWarning = "Warning: ";

bool isNumberStart(std::string_view s, std::size_t i) {
    const auto digit = [&](std::size_t k) { return k < s.size() && std::isdigit(static_cast<unsigned char>(s[k])); };
    if (digit(i)) return true;
    return (s[i] == '-' || s[i] == '.') && digit(i + 1);
}

}  // namespace

std::string SumoWarnings::kindOf(std::string_view message) {
    std::string kind;
    kind.reserve(message.size());
    std::size_t i = 0;
    while (i < message.size()) {
        const char c = message[i];
        if (c == '\'') {  // SUMO quotes ids: 'veh12', 'e_0'
            const std::size_t close = message.find('\'', i + 1);
            if (close != std::string_view::npos) {
                kind += "'…'";
                i = close + 1;
                continue;
            }
        }
        // A number standing alone (not the 2 of "e2"): time=12.00, 3 vehicles, -4.5.
        const bool alone = kind.empty() || !std::isalnum(static_cast<unsigned char>(kind.back()));
        if (alone && isNumberStart(message, i)) {
            ++i;
            // Digits, and a point only between digits: "time=23.00." keeps its full stop.
            while (i < message.size() && (std::isdigit(static_cast<unsigned char>(message[i])) ||
                                          (message[i] == '.' && i + 1 < message.size() &&
                                           std::isdigit(static_cast<unsigned char>(message[i + 1]))))) {
                ++i;
            }
            kind += '#';
            continue;
        }
        kind += c;
        ++i;
    }
    return kind;
}

void SumoWarnings::take(std::string_view printed) {
    std::string message;  // the warning being read: its first line and continuation lines
    std::string other;    // lines that are not warnings, passed on in one write
    const auto flush = [&] {
        if (!message.empty()) warning(message);
        message.clear();
    };
    std::size_t pos = 0;
    while (pos < printed.size()) {
        std::size_t eol = printed.find('\n', pos);
        eol = eol == std::string_view::npos ? printed.size() : eol + 1;
        const std::string_view line = printed.substr(pos, eol - pos);
        pos = eol;
        if (line.substr(0, kWarning.size()) == kWarning) {
            flush();
            message = line;
        } else if (!message.empty() && !line.empty() && (line[0] == ' ' || line[0] == '\t')) {
            message += line;  // an indented continuation of the warning
        } else {
            flush();
            other += line;
        }
    }
    flush();
    if (!other.empty()) std::fputs(other.c_str(), out_);
}

void SumoWarnings::warning(const std::string& message) {
    ++total_;
    if (log_ != nullptr) {
        *log_ << message;
        if (message.back() != '\n') *log_ << '\n';
    }
    std::string_view text(message);
    text.remove_prefix(kWarning.size());
    const std::size_t end = text.find('\n');
    const std::string pattern = kindOf(text.substr(0, end));
    const auto [it, inserted] = index_.try_emplace(pattern, kinds_.size());
    if (inserted) kinds_.push_back(Kind{pattern, 0});
    const std::size_t count = ++kinds_[it->second].count;
    if (count <= shown_) {
        std::fputs(message.c_str(), out_);
        if (message.back() != '\n') std::fputc('\n', out_);
    }
    if (count == shown_ + 1 && shown_ > 0) {
        std::size_t cut = std::min<std::size_t>(pattern.size(), 60);
        // Not inside a UTF-8 sequence (the pattern's '…' is three bytes).
        while (cut < pattern.size() && cut > 0 && (static_cast<unsigned char>(pattern[cut]) & 0xC0) == 0x80) --cut;
        const std::string_view shortPattern = std::string_view(pattern).substr(0, cut);
        std::fprintf(out_,
                     "sbsim: further SUMO warnings \"%.*s%s\" are only counted (--verbose shows them, "
                     "--sumo-log FILE keeps them)\n",
                     static_cast<int>(shortPattern.size()), shortPattern.data(), cut < pattern.size() ? "…" : "");
    }
}

std::vector<SumoWarnings::Kind> SumoWarnings::kinds() const {
    std::vector<Kind> out = kinds_;
    std::stable_sort(out.begin(), out.end(), [](const Kind& a, const Kind& b) { return a.count > b.count; });
    return out;
}

}  // namespace sbsim::traffic
