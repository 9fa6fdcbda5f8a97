#include "sbsim/app/outputs/XmlText.h"

#include <fmt/format.h>

#include <cstdint>

namespace sbsim::app {

namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

/// The length of the well-formed UTF-8 sequence at `text[i]` (1 to 4), its code point in `code`;
/// 0 if the bytes there are not one (overlong, a surrogate, beyond U+10FFFF, cut short).
std::size_t sequence(std::string_view text, std::size_t i, std::uint32_t& code) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    if (lead < 0x80) {
        code = lead;
        return 1;
    }
    // Per lead byte: the sequence's length, the lead's payload bits, the least code point (shorter is overlong).
    struct Form {
        unsigned char mask, value;
        std::size_t length;
        std::uint32_t min;
    };
    static constexpr Form kForms[] = {{0xE0, 0xC0, 2, 0x80}, {0xF0, 0xE0, 3, 0x800}, {0xF8, 0xF0, 4, 0x10000}};
    for (const Form& form : kForms) {
        if ((lead & form.mask) != form.value) continue;
        if (i + form.length > text.size()) return 0;
        code = lead & static_cast<unsigned char>(~form.mask);
        for (std::size_t k = 1; k < form.length; ++k) {
            if ((byte(i + k) & 0xC0) != 0x80) return 0;
            code = (code << 6) | (byte(i + k) & 0x3F);
        }
        if (code < form.min || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
        return form.length;
    }
    return 0;
}

}  // namespace

std::string xmlText(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        std::uint32_t code = 0;
        const std::size_t length = sequence(text, i, code);
        if (length == 0) {
            out += kReplacement;
            ++i;
        } else if (code < 0x20 && code != '\t' && code != '\n' && code != '\r') {
            out += fmt::format("\\x{:02x}", code);
            i += length;
        } else if (code == 0xFFFE || code == 0xFFFF) {
            out += fmt::format("\\u{:04x}", code);
            i += length;
        } else {
            out.append(text.substr(i, length));
            i += length;
        }
    }
    return out;
}

}  // namespace sbsim::app
