// The event log's lines: key order, times rounded to the millisecond in shortest form, strings
// escaped as JSON (and bytes that are not UTF-8 replaced instead of failing the run), and
// flushing left to the step's end.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "sbsim/storyboard/EventLog.h"

namespace sbsim::storyboard {
namespace {

using kernel::SimTime;

/// The one line an activation at `t` writes, without its newline.
std::string activationAt(SimTime t) {
    std::ostringstream out;
    EventLog(out).activate(t, "s", "v");
    std::string line = out.str();
    EXPECT_EQ(line.back(), '\n');
    line.pop_back();
    return line;
}

std::string timeField(SimTime t) {
    const std::string line = activationAt(t);
    return line.substr(0, line.find(','));
}

TEST(EventLog, TimesAreRoundedToTheMillisecondInShortestForm) {
    EXPECT_EQ(timeField(SimTime::fromSeconds(12.3)), R"({"t":12.3)");
    EXPECT_EQ(timeField(SimTime::zero()), R"({"t":0)");
    EXPECT_EQ(timeField(SimTime::fromSeconds(7.001)), R"({"t":7.001)");
    EXPECT_EQ(timeField(SimTime::fromSeconds(100)), R"({"t":100)");
    EXPECT_EQ(timeField(SimTime::fromSeconds(-1.5)), R"({"t":-1.5)");
    EXPECT_EQ(timeField(SimTime::fromNanoseconds(7'000'499'999)), R"({"t":7)");
    EXPECT_EQ(timeField(SimTime::fromNanoseconds(7'000'500'000)), R"({"t":7.001)");
    EXPECT_EQ(timeField(SimTime::fromNanoseconds(-2'999'500'000)), R"({"t":-3)");
    EXPECT_EQ(timeField(SimTime::fromNanoseconds(400'000)), R"({"t":0)");
    EXPECT_EQ(timeField(SimTime::fromNanoseconds(123'456'789'012)), R"({"t":123.457)");
}

TEST(EventLog, KeysComeInTheDocumentedOrder) {
    std::ostringstream out;
    EventLog log(out);
    log.activate(SimTime::fromSeconds(1), "rain", "flow0.1");
    log.deactivate(SimTime::fromSeconds(2), "rain", "flow0.1", "vehicle_left");
    log.signal(SimTime::fromSeconds(3), "siren", "police0", "siren on", {"a", "b"});
    log.signal(SimTime::fromSeconds(4), "siren", "police1", "alone", {});
    log.equipped(SimTime::fromSeconds(5.5), "flow0.2");
    EXPECT_EQ(out.str(),
              R"({"t":1,"type":"activate","story":"rain","vehicle":"flow0.1"})"
              "\n"
              R"({"t":2,"type":"deactivate","story":"rain","vehicle":"flow0.1","reason":"vehicle_left"})"
              "\n"
              R"({"t":3,"type":"signal","story":"siren","vehicle":"police0","cause":"siren on","others":["a","b"]})"
              "\n"
              R"({"t":4,"type":"signal","story":"siren","vehicle":"police1","cause":"alone","others":[]})"
              "\n"
              R"({"t":5.5,"type":"equipped","story":null,"vehicle":"flow0.2"})"
              "\n");
}

TEST(EventLog, StringsAreEscapedAndReadBackUnchanged) {
    const std::string story = "say \"hi\"\\ now\nand\ttab \x01 caf\xc3\xa9";
    const std::string vehicle = "veh/1 \xe2\x9c\x93";
    std::ostringstream out;
    EventLog(out).signal(SimTime::fromSeconds(1), story, vehicle, "c\r", {"o\"1", "o\x1f"});
    const std::string line = out.str();
    EXPECT_NE(line.find(R"(say \"hi\"\\ now\nand\ttab \u0001 café)"), std::string::npos) << line;
    EXPECT_EQ(line.find('\n'), line.size() - 1) << "one event, one line";
    const auto event = nlohmann::json::parse(line);
    EXPECT_EQ(event["story"], story);
    EXPECT_EQ(event["vehicle"], vehicle);
    EXPECT_EQ(event["cause"], "c\r");
    EXPECT_EQ(event["others"], (std::vector<std::string>{"o\"1", "o\x1f"}));
}

TEST(EventLog, BytesThatAreNotUtf8BecomeReplacementCharacters) {
    std::ostringstream out;
    EventLog log(out);
    EXPECT_NO_THROW(log.deactivate(SimTime::fromSeconds(1), "bad\xff", "v\xc3", "condition"));
    EXPECT_EQ(out.str(),
              "{\"t\":1,\"type\":\"deactivate\",\"story\":\"bad\xef\xbf\xbd\",\"vehicle\":\"v\xef\xbf\xbd\","
              "\"reason\":\"condition\"}\n");
}

/// A string buffer that counts how often its stream was flushed.
class CountingBuffer : public std::stringbuf {
public:
    int syncs = 0;

protected:
    int sync() override {
        ++syncs;
        return std::stringbuf::sync();
    }
};

TEST(EventLog, FlushesOnlyWhenAsked) {
    CountingBuffer buffer;
    std::ostream out(&buffer);
    EventLog log(out);
    log.activate(SimTime::fromSeconds(1), "s", "a");
    log.signal(SimTime::fromSeconds(1), "s", "a", "c", {"b"});
    EXPECT_EQ(buffer.syncs, 0) << "lines are not flushed one by one";
    log.flush();
    EXPECT_EQ(buffer.syncs, 1);
    const std::string text = buffer.str();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2);
}

}  // namespace
}  // namespace sbsim::storyboard
