#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/storyboard/Criterion.h"

namespace sbsim::app {

/// The criteria's verdicts as JUnit XML (--junit), what CI servers read: one <testsuite> named
/// `suite` (the story file), one <testcase> per criterion, a failed one with a <failure> whose
/// message gives the actual and the expected value. Well-formed XML 1.0 whatever the names and
/// values hold (see xmlText).
void writeJUnit(std::ostream& out, const std::string& suite,
                const std::vector<std::pair<std::string, storyboard::CriterionVerdict>>& verdicts, double seconds);

}  // namespace sbsim::app
