#include "sbsim/kernel/OneLine.h"

#include <gtest/gtest.h>

namespace sbsim::kernel {
namespace {

TEST(OneLine, RunsOfWhiteSpaceBecomeOneSpaceAndTheEndsAreTrimmed) {
    EXPECT_EQ(oneLine("  Error: edge 'a'\n\tnot known\r\n"), "Error: edge 'a' not known");
    EXPECT_EQ(oneLine("\n\n"), "");
    EXPECT_EQ(oneLine("plain"), "plain");
}

TEST(OneLine, EscapeControlsKeepsWhatTheUserTypedVisibleOnOneLine) {
    // Found by the command-line fuzzing: an argument "\r" made the error two lines, the second
    // one starting with nothing a reader could see.
    EXPECT_EQ(escapeControls("not expected: \r"), "not expected: \\r");
    EXPECT_EQ(escapeControls("a\nb\tc"), "a\\nb\\tc");
    EXPECT_EQ(escapeControls(std::string_view("\x1b[31m\x7f\0", 7)), "\\x1b[31m\\x7f\\x00");
    EXPECT_EQ(escapeControls("grün → ok"), "grün → ok") << "UTF-8 passes unchanged";
}

}  // namespace
}  // namespace sbsim::kernel
