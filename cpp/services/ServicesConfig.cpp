#include "sbsim/services/ServicesConfig.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "sbsim/services/XmlDocument.h"

namespace sbsim::services {

namespace {

[[noreturn]] void fail(const std::string& source, int line, const std::string& message) {
    throw ServicesConfigError(source + ":" + std::to_string(line) + ": " + message);
}

std::string_view trimmed(std::string_view s) {
    constexpr std::string_view kBlanks = " \t\n\r";
    const std::size_t first = s.find_first_not_of(kBlanks);
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(kBlanks) - first + 1);
}

// Character data where the format has none is most likely a misplaced value: say so.
void rejectText(const XmlElement& element, const std::string& source) {
    if (!element.text.empty()) fail(source, element.line, "unexpected text in <" + element.name + ">");
}

void rejectAttributes(const XmlElement& element, const std::string& source) {
    if (!element.attributes.empty()) {
        fail(source, element.line,
             "unexpected attribute '" + element.attributes.front().first + "' on <" + element.name + ">");
    }
}

ServiceFilter parseFilter(const XmlElement& element, const std::string& source) {
    ServiceFilter filter;
    filter.line = element.line;
    filter.subject = element.name == "type" ? ServiceFilter::Subject::VehicleType : ServiceFilter::Subject::VehicleId;
    bool hasPattern = false;
    for (const auto& [key, value] : element.attributes) {
        if (key == "pattern") {
            filter.pattern = value;
            hasPattern = true;
        } else if (key == "match") {
            if (value != "inverse") {
                fail(source, element.line,
                     "unknown match '" + value + "' in <" + element.name + "> filter (the only value is 'inverse')");
            }
            filter.inverse = true;
        } else if (key == "rate") {
            // Artery draws a random number per vehicle here; we have no random stream for it (yet).
            fail(source, element.line, "the 'rate' attribute of <" + element.name + "> filters is not supported");
        } else {
            fail(source, element.line, "unexpected attribute '" + key + "' on <" + element.name + "> filter");
        }
    }
    if (!hasPattern) fail(source, element.line, "<" + element.name + "> filter has no 'pattern' attribute");
    try {
        filter.regex = std::regex(filter.pattern, std::regex::ECMAScript | std::regex::optimize);
    } catch (const std::regex_error& e) {
        fail(source, element.line,
             "invalid pattern '" + filter.pattern + "' in <" + element.name + "> filter: " + e.what());
    }
    rejectText(element, source);
    return filter;
}

void parseFilters(const XmlElement& element, const std::string& source, ServiceSpec& spec) {
    for (const auto& [key, value] : element.attributes) {
        if (key != "operator") fail(source, element.line, "unexpected attribute '" + key + "' on <filters>");
        if (value == "and") {
            spec.combine = ServiceSpec::Combine::All;
        } else if (value == "or") {
            spec.combine = ServiceSpec::Combine::Any;
        } else {
            fail(source, element.line, "unknown filter operator '" + value + "' (expected 'and' or 'or')");
        }
    }
    rejectText(element, source);
    for (const XmlElement& child : element.children) {
        if (child.name == "name" || child.name == "type") {
            spec.filters.push_back(parseFilter(child, source));
        } else if (child.name == "penetration") {
            fail(source, child.line, "<penetration> filters are not supported (they need a random draw per vehicle)");
        } else {
            fail(source, child.line, "unknown filter <" + child.name + "> (expected <name> or <type>)");
        }
    }
}

ServiceSpec parseService(const XmlElement& element, const std::string& source) {
    ServiceSpec spec;
    spec.source = source;
    spec.line = element.line;
    const std::string* type = element.attribute("type");
    if (!type) fail(source, element.line, "<service> has no 'type' attribute");
    if (trimmed(*type).empty()) fail(source, element.line, "<service> has an empty 'type' attribute");
    spec.type = *type;
    for (const auto& [key, value] : element.attributes) {
        if (key != "type") spec.parameters.emplace(key, value);
    }
    rejectText(element, source);
    bool hasFilters = false;
    for (const XmlElement& child : element.children) {
        if (child.name == "listener") continue;  // Artery's port binding; services here talk in-process
        if (child.name != "filters") {
            fail(source, child.line,
                 "unexpected element <" + child.name + "> in <service> (expected <filters> or <listener>)");
        }
        if (hasFilters) fail(source, child.line, "a <service> may have only one <filters>");
        hasFilters = true;
        parseFilters(child, source, spec);
    }
    return spec;
}

void readServices(const XmlElement& root, const std::string& source, std::vector<ServiceSpec>& out) {
    if (root.name != "services") {
        fail(source, root.line, "the root element must be <services>, found <" + root.name + ">");
    }
    rejectAttributes(root, source);
    rejectText(root, source);
    for (const XmlElement& child : root.children) {
        if (child.name != "service") {
            fail(source, child.line, "unexpected element <" + child.name + "> in <services> (expected <service>)");
        }
        out.push_back(parseService(child, source));
    }
}

}  // namespace

bool ServiceFilter::matches(std::string_view vehicleId, std::string_view vehicleType) const {
    const std::string_view subjectText = subject == Subject::VehicleId ? vehicleId : vehicleType;
    return std::regex_match(subjectText.begin(), subjectText.end(), regex) != inverse;
}

bool ServiceSpec::matches(std::string_view vehicleId, std::string_view vehicleType) const {
    const auto passes = [&](const ServiceFilter& f) { return f.matches(vehicleId, vehicleType); };
    if (filters.empty()) return true;
    return combine == Combine::All ? std::all_of(filters.begin(), filters.end(), passes)
                                   : std::any_of(filters.begin(), filters.end(), passes);
}

std::optional<std::string> ServiceSpec::parameter(std::string_view name) const {
    const auto it = parameters.find(name);
    if (it == parameters.end()) return std::nullopt;
    return it->second;
}

void ServiceSpec::badParameter(std::string_view name, std::string_view expected) const {
    fail(source, line,
         "parameter '" + std::string(name) + "' of service '" + type + "' must be " + std::string(expected) +
             ", got '" + parameters.find(name)->second + "'");
}

double ServiceSpec::number(std::string_view name, double fallback) const {
    const auto it = parameters.find(name);
    if (it == parameters.end()) return fallback;
    std::string_view text = trimmed(it->second);
    // from_chars takes no '+' sign; allow one in front of a digit or a point.
    if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
        badParameter(name, "a number");
    }
    return value;
}

bool ServiceSpec::boolean(std::string_view name, bool fallback) const {
    const auto it = parameters.find(name);
    if (it == parameters.end()) return fallback;
    const std::string_view text = trimmed(it->second);
    if (text == "true" || text == "1") return true;
    if (text == "false" || text == "0") return false;
    badParameter(name, "true or false");
}

ServicesConfig ServicesConfig::parse(std::string_view text, const std::string& source) {
    ServicesConfig config;
    try {
        readServices(parseXml(text, source), source, config.services_);
    } catch (const XmlError& e) {
        // One exception type for callers: a broken file is a broken services file.
        throw ServicesConfigError(e.what());
    }
    return config;
}

ServicesConfig ServicesConfig::load(const std::filesystem::path& path) {
    ServicesConfig config;
    try {
        readServices(readXmlFile(path), path.string(), config.services_);
    } catch (const XmlError& e) {
        throw ServicesConfigError(e.what());
    }
    return config;
}

std::vector<const ServiceSpec*> ServicesConfig::matching(std::string_view vehicleId,
                                                         std::string_view vehicleType) const {
    std::vector<const ServiceSpec*> out;
    for (const ServiceSpec& spec : services_) {
        if (spec.matches(vehicleId, vehicleType)) out.push_back(&spec);
    }
    return out;
}

}  // namespace sbsim::services
