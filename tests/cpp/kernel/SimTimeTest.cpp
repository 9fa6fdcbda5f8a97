#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "TestPrinters.h"
#include "ThrownMessage.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::kernel {
namespace {

TEST(SimTime, DefaultIsZero) {
    EXPECT_EQ(SimTime().raw(), 0);
    EXPECT_EQ(SimTime(), SimTime::zero());
}

TEST(SimTime, AddingATenthTenThousandTimesIsExact) {
    // The premise: the same sum in doubles drifts.
    double seconds = 0;
    for (int i = 0; i < 10'000; ++i) seconds += 0.1;
    ASSERT_NE(seconds, 1000.0);

    const SimTime tenth = SimTime::fromSeconds(0.1);
    SimTime t;
    for (int i = 0; i < 10'000; ++i) t += tenth;
    EXPECT_EQ(t.raw(), 1000 * SimTime::kPerSecond);
    EXPECT_EQ(t, SimTime::fromSeconds(1000));
    EXPECT_EQ(t, SimTime::fromMilliseconds(1'000'000));
    EXPECT_EQ(t.str(), "1000");
}

TEST(SimTime, FromSecondsRoundsToTheNearestNanosecond) {
    EXPECT_EQ(SimTime::fromSeconds(0.1).raw(), 100'000'000);
    EXPECT_EQ(SimTime::fromSeconds(12.3).raw(), 12'300'000'000);
    EXPECT_EQ(SimTime::fromSeconds(1e-9).raw(), 1);
    EXPECT_EQ(SimTime::fromSeconds(0.4e-9).raw(), 0);
    EXPECT_EQ(SimTime::fromSeconds(0.6e-9).raw(), 1);
    EXPECT_EQ(SimTime::fromSeconds(1.0000000004).raw(), 1'000'000'000);
    EXPECT_EQ(SimTime::fromSeconds(1.0000000006).raw(), 1'000'000'001);
    EXPECT_EQ(SimTime::fromSeconds(-1.5).raw(), -1'500'000'000);
    EXPECT_EQ(SimTime::fromSeconds(-0.6e-9).raw(), -1);
    // 0.3 is 0.29999999999999998890 as a double: rounding, not truncation, gives 0.3 s.
    EXPECT_EQ(SimTime::fromSeconds(0.3).raw(), 300'000'000);
    EXPECT_EQ(SimTime::fromSeconds(9e9).raw(), 9'000'000'000'000'000'000);
}

TEST(SimTime, FromSecondsOutOfRangeThrows) {
    EXPECT_THROW(SimTime::fromSeconds(1e10), std::out_of_range);
    EXPECT_THROW(SimTime::fromSeconds(-1e10), std::out_of_range);
    EXPECT_THROW(SimTime::fromSeconds(std::numeric_limits<double>::infinity()), std::out_of_range);
    EXPECT_THROW(SimTime::fromSeconds(-std::numeric_limits<double>::infinity()), std::out_of_range);
    EXPECT_THROW(SimTime::fromSeconds(std::nan("")), std::out_of_range);
    EXPECT_NO_THROW(SimTime::fromSeconds(-9e9));
    using testing_support::thrownMessage;
    EXPECT_EQ(thrownMessage([] { SimTime::fromSeconds(-1e10); }),
              "simulation time out of range: -10000000000.000000 s");
    EXPECT_EQ(thrownMessage([] { SimTime::fromSeconds(std::numeric_limits<double>::infinity()); }),
              "simulation time out of range: inf s");
}

TEST(SimTime, MillisecondsAndNanoseconds) {
    EXPECT_EQ(SimTime::fromMilliseconds(1500).raw(), 1'500'000'000);
    EXPECT_EQ(SimTime::fromMilliseconds(1500).milliseconds(), 1500);
    EXPECT_EQ(SimTime::fromMilliseconds(-7).raw(), -7'000'000);
    EXPECT_EQ(SimTime::fromNanoseconds(1'999'999).milliseconds(), 1);  // truncates
    EXPECT_EQ(SimTime::fromNanoseconds(42).raw(), 42);
    EXPECT_EQ(SimTime::fromRaw(42), SimTime::fromNanoseconds(42));
    EXPECT_DOUBLE_EQ(SimTime::fromMilliseconds(1500).seconds(), 1.5);
    EXPECT_EQ(SimTime::fromSeconds(0.001), SimTime::fromMilliseconds(1));
    // Every SUMO millisecond time converts back and forth exactly.
    for (SimTime::rep ms = 0; ms < 100'000; ms += 7) {
        ASSERT_EQ(SimTime::fromMilliseconds(ms).milliseconds(), ms);
        ASSERT_EQ(SimTime::fromSeconds(static_cast<double>(ms) / 1000), SimTime::fromMilliseconds(ms)) << ms;
    }
}

TEST(SimTime, StrIsShortestDecimalSeconds) {
    EXPECT_EQ(SimTime::fromSeconds(12.3).str(), "12.3");
    EXPECT_EQ(SimTime::zero().str(), "0");
    EXPECT_EQ(SimTime::fromSeconds(-1.5).str(), "-1.5");
    EXPECT_EQ(SimTime::fromNanoseconds(1).str(), "0.000000001");
    EXPECT_EQ(SimTime::fromNanoseconds(-1).str(), "-0.000000001");
    EXPECT_EQ(SimTime::fromMilliseconds(1).str(), "0.001");
    EXPECT_EQ(SimTime::fromSeconds(1).str(), "1");
    EXPECT_EQ(SimTime::fromSeconds(100).str(), "100");  // zeros of the integer part stay
    EXPECT_EQ(SimTime::fromSeconds(-100).str(), "-100");
    EXPECT_EQ(SimTime::fromMilliseconds(1050).str(), "1.05");
    EXPECT_EQ(SimTime::fromNanoseconds(1'000'000'010).str(), "1.00000001");
    EXPECT_EQ(SimTime::max().str(), "9223372036.854775807");
    EXPECT_EQ(SimTime::fromRaw(std::numeric_limits<SimTime::rep>::min()).str(), "-9223372036.854775808");
}

TEST(SimTime, Comparisons) {
    const SimTime a = SimTime::fromMilliseconds(1);
    const SimTime b = SimTime::fromNanoseconds(1'000'001);
    EXPECT_LT(a, b);
    EXPECT_LE(a, b);
    EXPECT_GT(b, a);
    EXPECT_NE(a, b);
    EXPECT_EQ(a, SimTime::fromNanoseconds(1'000'000));
    EXPECT_LT(-a, SimTime::zero());
    EXPECT_LT(SimTime::fromSeconds(1e9), SimTime::max());
    EXPECT_TRUE((a <=> b) < 0);
}

TEST(SimTime, Arithmetic) {
    const SimTime s = SimTime::fromSeconds(1);
    const SimTime ms = SimTime::fromMilliseconds(1);
    EXPECT_EQ(s + ms, SimTime::fromMilliseconds(1001));
    EXPECT_EQ(s - ms, SimTime::fromMilliseconds(999));
    EXPECT_EQ(ms - s, SimTime::fromMilliseconds(-999));
    EXPECT_EQ(-s, SimTime::fromSeconds(-1));
    EXPECT_EQ(ms * 1000, s);
    EXPECT_EQ(s / ms, 1000);
    EXPECT_EQ(SimTime::fromMilliseconds(2500) % s, SimTime::fromMilliseconds(500));
    SimTime t = s;
    t -= ms;
    t -= ms;
    EXPECT_EQ(t, SimTime::fromMilliseconds(998));
}

TEST(SimTime, ArithmeticBeyondTheRangeThrowsInsteadOfWrapping) {
    const SimTime far = SimTime::fromSeconds(9e9);
    EXPECT_THROW((void)(far + far), std::out_of_range);
    EXPECT_THROW((void)(-far - far), std::out_of_range);
    SimTime t = far;
    EXPECT_THROW(t += far, std::out_of_range);
    EXPECT_EQ(t, far) << "a failed += leaves the time as it was";
    EXPECT_EQ((far - far).raw(), 0);
}

}  // namespace
}  // namespace sbsim::kernel
