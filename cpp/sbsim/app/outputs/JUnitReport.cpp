#include "sbsim/app/outputs/JUnitReport.h"

#include <tinyxml2.h>

#include <fmt/format.h>

#include <cstddef>
#include <cstdint>

namespace sbsim::app {

namespace {

/// The length of the well-formed UTF-8 sequence at `s[i]` allowed in XML 1.0, or 0: a criterion's
/// name and values are the story's strings, which may hold anything.
std::size_t xmlCharLength(const std::string& s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = byte(i);
    if (c < 0x80) return (c >= 0x20 || c == '\t' || c == '\n' || c == '\r') && c != 0x7f ? 1 : 0;
    const std::size_t n = c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 ? 2 : 0;
    if (n == 0 || c > 0xf4 || i + n > s.size()) return 0;
    std::uint32_t code = c & (0x7f >> n);
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xc0) != 0x80) return 0;
        code = (code << 6) | (byte(i + k) & 0x3f);
    }
    const std::uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
    const bool allowed = code >= least[n] && code <= 0x10ffff && !(code >= 0xd800 && code <= 0xdfff) &&
                         !(code >= 0x7f && code <= 0x9f) && code != 0xfffe && code != 0xffff;
    return allowed ? n : 0;
}

}  // namespace

std::string xmlText(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size();) {
        if (const std::size_t n = xmlCharLength(s, i); n > 0) {
            out.append(s, i, n);
            i += n;
        } else {
            // Shown, not dropped: a reader sees which byte the string held.
            out += fmt::format("\\x{:02x}", static_cast<unsigned char>(s[i]));
            ++i;
        }
    }
    return out;
}

void writeJUnit(std::ostream& out, const std::string& suite,
                const std::vector<std::pair<std::string, storyboard::CriterionVerdict>>& verdicts, double seconds) {
    std::size_t failures = 0;
    for (const auto& [name, v] : verdicts) failures += v.passed ? 0 : 1;
    tinyxml2::XMLDocument doc;
    doc.InsertEndChild(doc.NewDeclaration());
    tinyxml2::XMLElement* suites = doc.NewElement("testsuites");
    doc.InsertEndChild(suites);
    tinyxml2::XMLElement* s = suites->InsertNewChildElement("testsuite");
    const std::string suiteName = xmlText(suite);
    s->SetAttribute("name", suiteName.c_str());
    s->SetAttribute("tests", static_cast<std::int64_t>(verdicts.size()));
    s->SetAttribute("failures", static_cast<std::int64_t>(failures));
    s->SetAttribute("errors", 0);
    s->SetAttribute("time", seconds);
    for (const auto& [name, v] : verdicts) {
        tinyxml2::XMLElement* c = s->InsertNewChildElement("testcase");
        c->SetAttribute("name", xmlText(name).c_str());
        c->SetAttribute("classname", suiteName.c_str());
        const std::string text = xmlText("actual: " + v.actual + "; expected: " + v.expected);
        if (v.passed) {
            c->InsertNewChildElement("system-out")->SetText(text.c_str());
        } else {
            tinyxml2::XMLElement* f = c->InsertNewChildElement("failure");
            f->SetAttribute("message", text.c_str());
            f->SetAttribute("type", "criterion");
            f->SetText(text.c_str());
        }
    }
    tinyxml2::XMLPrinter printer;
    doc.Print(&printer);
    out << printer.CStr();
}

}  // namespace sbsim::app
