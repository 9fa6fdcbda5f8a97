#include "sbsim/app/outputs/JUnitReport.h"

#include <tinyxml2.h>

#include <cstddef>

#include "sbsim/app/outputs/XmlText.h"

namespace sbsim::app {

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
