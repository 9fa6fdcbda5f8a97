#include "sbsim/kernel/StudyParameters.h"

#include <gtest/gtest.h>

namespace sbsim::kernel {
namespace {

using Value = StudyParameters::Value;

TEST(StudyParameters, ValuesAreTypedAsWritten) {
    EXPECT_EQ(StudyParameters::parse("true"), Value(true));
    EXPECT_EQ(StudyParameters::parse("false"), Value(false));
    EXPECT_EQ(StudyParameters::parse("10"), Value(std::int64_t{10}));
    EXPECT_EQ(StudyParameters::parse("-3"), Value(std::int64_t{-3}));
    EXPECT_EQ(StudyParameters::parse("2.5"), Value(2.5));
    EXPECT_EQ(StudyParameters::parse("1e3"), Value(1000.0));
    EXPECT_EQ(StudyParameters::parse("True"), Value(std::string("True"))) << "only lower-case booleans";
    EXPECT_EQ(StudyParameters::parse("nan"), Value(std::string("nan"))) << "no NaN or infinity as a number";
    EXPECT_EQ(StudyParameters::parse(""), Value(std::string()));
    EXPECT_EQ(StudyParameters::parse("99999999999999999999"), Value(99999999999999999999.0)) << "beyond int64: a float";
    EXPECT_EQ(StudyParameters::parse("a=b"), Value(std::string("a=b")));
}

TEST(StudyParameters, FormatKeepsTheTypeVisible) {
    EXPECT_EQ(StudyParameters::format(Value(10.0)), "10.0");
    EXPECT_EQ(StudyParameters::format(Value(std::int64_t{10})), "10");
    EXPECT_EQ(StudyParameters::format(Value(true)), "true");
    EXPECT_EQ(StudyParameters::format(Value(0.1)), "0.1");
    EXPECT_EQ(StudyParameters::format(Value(std::string("wet"))), "wet");
}

TEST(StudyParameters, AddSplitsAtTheFirstEqualsSign) {
    StudyParameters p;
    p.add("rain_speed=10");
    p.add("label=a=b");
    EXPECT_EQ(p.get("rain_speed"), Value(std::int64_t{10}));
    EXPECT_EQ(p.get("label"), Value(std::string("a=b")));
    EXPECT_FALSE(p.get("missing").has_value());
}

TEST(StudyParameters, BadAssignmentsNameTheProblem) {
    StudyParameters p;
    p.add("x=1");
    const auto message = [&](const char* text) {
        try {
            p.add(text);
        } catch (const StudyParameterError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("rain"), "expects NAME=VALUE, got 'rain'");
    EXPECT_EQ(message("=5"), "'' is not a parameter name (letters, digits, '_', '.', '-'; not starting with a digit)");
    EXPECT_EQ(message("1x=5"),
              "'1x' is not a parameter name (letters, digits, '_', '.', '-'; not starting with a digit)");
    EXPECT_EQ(message("x=2"), "'x' is given twice");
}

TEST(StudyParameters, UnreadListsWhatNobodyAskedFor) {
    StudyParameters p;
    p.add("b=1");
    p.add("a=2");
    p.add("c=3");
    EXPECT_EQ(p.unread(), (std::vector<std::string>{"a", "b", "c"}));
    (void)p.get("b");
    EXPECT_TRUE(p.contains("a"));
    EXPECT_EQ(p.unread(), (std::vector<std::string>{"a", "c"})) << "contains() is not a read";
    (void)p.all();
    EXPECT_EQ(p.unread(), (std::vector<std::string>{"a", "c"})) << "all() is not a read";
}

}  // namespace
}  // namespace sbsim::kernel
