#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/storyboard/Criterion.h"

namespace sbsim::app {

/// The criteria's verdicts as JUnit XML (--junit), what CI servers read: one <testsuite> named
/// `suite` (the story file), one <testcase> per criterion, a failed one with a <failure> whose
/// message gives the actual and the expected value.
/// `s` with what XML 1.0 cannot hold (control characters, malformed UTF-8) written as `\xNN`, so
/// the file stays well-formed whatever a story names its criteria or reports as values.
std::string xmlText(const std::string& s);

void writeJUnit(std::ostream& out, const std::string& suite,
                const std::vector<std::pair<std::string, storyboard::CriterionVerdict>>& verdicts, double seconds);

}  // namespace sbsim::app
