#include "sbsim/traffic/SumoWarnings.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>

namespace sbsim::traffic {
namespace {

/// What a SumoWarnings wrote to its stream, read back from a temporary file.
class Shown {
public:
    Shown() : file_(std::tmpfile()) {}
    ~Shown() { std::fclose(file_); }
    std::FILE* file() { return file_; }
    std::string text() {
        std::fflush(file_);
        std::rewind(file_);
        std::string out;
        for (int c = std::fgetc(file_); c != EOF; c = std::fgetc(file_)) out += static_cast<char>(c);
        return out;
    }

private:
    std::FILE* file_;
};

std::string braking(const std::string& id, int t) {
    return "Warning: Vehicle '" + id + "' performs emergency braking on lane 'e_0' with decel=9.00, wished=4.50, " +
           "severity=1.00, time=" + std::to_string(t) + ".00.\n";
}

TEST(SumoWarnings, KindsBlankNamesAndNumbersButKeepWords) {
    EXPECT_EQ(SumoWarnings::kindOf("Vehicle 'a' performs emergency braking with decel=9.00, time=12.00."),
              "Vehicle '…' performs emergency braking with decel=#, time=#.");
    EXPECT_EQ(SumoWarnings::kindOf("3 vehicles on e2 at -4.5 m"), "# vehicles on e2 at # m");
    EXPECT_EQ(SumoWarnings::kindOf(braking("x", 1).substr(9)), SumoWarnings::kindOf(braking("yy", 200).substr(9)));
}

TEST(SumoWarnings, ShowsTheFirstFewOfEachKindAndCountsAll) {
    Shown shown;
    std::ostringstream log;
    SumoWarnings warnings(2, shown.file());
    warnings.setLog(&log);
    std::string printed;
    for (int k = 0; k < 5; ++k) printed += braking("v" + std::to_string(k), k);
    printed += "Loading done.\n";
    printed += "Warning: Teleporting vehicle 'v9'; waited too long (jam), lane='e_0', time=7.00.\n";
    warnings.take(printed);
    warnings.take(braking("v5", 5));

    EXPECT_EQ(warnings.total(), 7U);
    const auto kinds = warnings.kinds();
    ASSERT_EQ(kinds.size(), 2U);
    EXPECT_EQ(kinds[0].count, 6U);
    EXPECT_EQ(kinds[1].count, 1U);
    EXPECT_EQ(kinds[1].pattern, "Teleporting vehicle '…'; waited too long (jam), lane='…', time=#.");
    const std::string text = shown.text();
    EXPECT_NE(text.find("'v0'"), std::string::npos);
    EXPECT_NE(text.find("'v1'"), std::string::npos);
    EXPECT_EQ(text.find("'v2'"), std::string::npos);             // counted, not shown
    EXPECT_NE(text.find("Loading done.\n"), std::string::npos);  // not a warning: passed on
    EXPECT_NE(text.find("'v9'"), std::string::npos);
    EXPECT_NE(text.find("are only counted"), std::string::npos);
    // The log has every warning, as printed.
    std::string expected;
    for (int k = 0; k < 5; ++k) expected += braking("v" + std::to_string(k), k);
    expected += "Warning: Teleporting vehicle 'v9'; waited too long (jam), lane='e_0', time=7.00.\n" + braking("v5", 5);
    EXPECT_EQ(log.str(), expected);
}

TEST(SumoWarnings, IndentedLinesBelongToTheirWarningAndVerboseShowsAll) {
    Shown shown;
    SumoWarnings warnings(SIZE_MAX, shown.file());
    warnings.take("Warning: first line\n  second line\nWarning: other\n");
    for (int k = 0; k < 10; ++k) warnings.take(braking("v", k));
    EXPECT_EQ(warnings.total(), 12U);
    const std::string text = shown.text();
    EXPECT_NE(text.find("Warning: first line\n  second line\n"), std::string::npos);
    EXPECT_EQ(text.find("only counted"), std::string::npos);
}

}  // namespace
}  // namespace sbsim::traffic
