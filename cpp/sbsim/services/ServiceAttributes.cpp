#include "sbsim/services/ServiceAttributes.h"

#include <fmt/format.h>

#include <cmath>

#include "sbsim/services/ServicesConfig.h"

namespace sbsim::services {

namespace {

using Kind = AttributeRule::Kind;

constexpr AttributeRule number(double min, double max, const char* unit) { return {Kind::Number, min, max, unit}; }
constexpr AttributeRule whole(double min, double max) { return {Kind::Whole, min, max, ""}; }
constexpr AttributeRule kDuration{Kind::Duration, ServiceSpec::kMinDurationSeconds, ServiceSpec::kMaxDurationSeconds,
                                  "s"};
constexpr AttributeRule kBoolean{Kind::Boolean, 0, 1, ""};
constexpr AttributeRule kText{Kind::Text, 0, 0, ""};
// ETSI's CauseCodeType, SubCauseCodeType and GeoNetworking's traffic class are one byte each.
constexpr AttributeRule kByte = whole(0, 255);
// Distances on the map: no network is wider than 10,000 km.
constexpr AttributeRule kDistance = number(0, 1e7, "m");
constexpr AttributeRule kArea = number(1, 1e7, "m");
constexpr AttributeRule kCoordinate = number(-1e7, 1e7, "m");
constexpr AttributeRule kSimTime = number(0, ServiceSpec::kMaxDurationSeconds, "s");

/// A pair of attributes where the first may not exceed the second, with their defaults.
struct Ordered {
    const char* type;
    const char* lower;
    double lowerDefault;
    const char* upper;
    double upperDefault;
};
constexpr Ordered kOrdered[] = {{"CaService", "minInterval", 0.1, "maxInterval", 1.0}};

std::map<std::string, std::map<std::string, AttributeRule>> makeRules() {
    std::map<std::string, std::map<std::string, AttributeRule>> rules{
        {"CaService",
         {{"minInterval", kDuration},
          {"maxInterval", kDuration},
          {"headingDelta", number(0, 360, "°")},
          {"positionDelta", number(0, 1e7, "m")},
          {"speedDelta", number(0, 1e3, "m/s")},
          {"fixedRate", kBoolean},
          {"withDccRestriction", kBoolean}}},
        {"RsuCaService", {{"generationInterval", kDuration}}},
        {"Beacon", {{"interval", kDuration}, {"bytes", whole(1, 2304)}}},
        {"DenService", {{"useCases", kText}}},
        {"RsuDenService",
         {{"cause", kByte},
          {"subcause", kByte},
          {"relevance", kDistance},
          {"trafficClass", kByte},
          {"area", kArea},
          {"x", kCoordinate},
          {"y", kCoordinate},
          {"from", kSimTime},
          {"until", kSimTime},
          {"interval", kDuration},
          {"validity", kDuration}}},
        {"ClearLaneService", {{"speed", number(0, 1e3, "m/s")}}},
        {"PoliceService", {}},
        {"PoliceServiceStoryboard", {{"cause", kText}}},
        // DEN use cases (<usecase> of a use-case file).
        {"StoryboardEvent",
         {{"signal", kText},
          {"endSignal", kText},
          {"cause", kByte},
          {"subcause", kByte},
          {"relevance", kDistance},
          {"trafficClass", kByte},
          {"area", kArea},
          {"validity", kDuration},
          {"interval", kDuration},
          {"duration", kDuration}}},
        {"EmergencyBrakeLight",
         {{"sampleDuration", kDuration},
          {"sampleInterval", kDuration},
          {"detectionBlockingInterval", kDuration},
          {"speedThreshold", number(0, 1e3, "m/s")},
          {"decelerationThreshold", number(0, 1e3, "m/s²")}}},
        {"TractionLoss", {{"detectionBlockingInterval", kDuration}}},
        {"TrafficJamEndOfQueue",
         {{"sampleDuration", kDuration},
          {"sampleInterval", kDuration},
          {"nonUrbanEnvironment", whole(0, 1)},
          {"detectionBlockingInterval", kDuration}}},
        {"TrafficJamAhead",
         {{"sampleDuration", kDuration},
          {"sampleInterval", kDuration},
          {"nonUrbanEnvironment", whole(0, 1)},
          {"detectionBlockingInterval", kDuration}}},
        {"ImpactReductionContainerExchange", {}},
    };
    for (auto& [type, attributes] : rules) attributes.emplace("name", kText);  // Artery's label
    return rules;
}

[[noreturn]] void fail(const ServiceSpec& spec, const std::string& message) {
    throw ServicesConfigError(fmt::format("{}:{}: {}", spec.source, spec.line, message));
}

std::string names(const std::map<std::string, AttributeRule>& attributes) {
    std::string out;
    for (const auto& [name, rule] : attributes) out += (out.empty() ? "" : ", ") + name;
    return out.empty() ? "none" : out;
}

}  // namespace

std::string AttributeRule::expected() const {
    const std::string unitText = *unit != '\0' ? fmt::format(" {}", unit) : std::string();
    switch (kind) {
        case Kind::Number:
            return fmt::format("a number from {:g} to {:g}{}", min, max, unitText);
        case Kind::Whole:
            return fmt::format("a whole number from {:g} to {:g}", min, max);
        case Kind::Duration:
            return fmt::format("a duration from {:g} to {:g} s", min, max);
        case Kind::Boolean:
            return "true or false";
        case Kind::Text:
            return "text";
    }
    return "";
}

const std::map<std::string, std::map<std::string, AttributeRule>>& attributeRules() {
    static const auto rules = makeRules();
    return rules;
}

void checkAttributes(const ServiceSpec& spec) {
    const auto found = attributeRules().find(spec.type);
    if (found == attributeRules().end()) return;
    const std::map<std::string, AttributeRule>& attributes = found->second;
    for (const auto& [name, value] : spec.parameters) {
        const auto rule = attributes.find(name);
        if (rule == attributes.end()) {
            fail(spec, fmt::format("unknown attribute '{}' of service '{}' (it takes: {})", name, spec.type,
                                   names(attributes)));
        }
        switch (rule->second.kind) {
            case Kind::Text:
                break;
            case Kind::Boolean:
                (void)spec.boolean(name, false);  // throws for anything else
                break;
            case Kind::Duration:
                (void)spec.duration(name, 1.0);
                break;
            case Kind::Number:
            case Kind::Whole: {
                const double v = spec.number(name, 0);  // throws unless a finite number
                const bool whole = rule->second.kind == Kind::Whole;
                if (v < rule->second.min || v > rule->second.max || (whole && v != std::floor(v))) {
                    fail(spec, fmt::format("parameter '{}' of service '{}' must be {}, got '{}'", name, spec.type,
                                           rule->second.expected(), value));
                }
                break;
            }
        }
    }
    for (const Ordered& o : kOrdered) {
        if (spec.type != o.type) continue;
        const double lower = spec.number(o.lower, o.lowerDefault);
        const double upper = spec.number(o.upper, o.upperDefault);
        if (lower > upper) {
            fail(spec, fmt::format("service '{}': {} ({:g} s) is above {} ({:g} s)", spec.type, o.lower, lower, o.upper,
                                   upper));
        }
    }
}

}  // namespace sbsim::services
