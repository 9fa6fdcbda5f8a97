#include "sbsim/services/ServicesConfig.h"

#include <fmt/format.h>
#include <re2/re2.h>
#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "sbsim/services/ServiceAttributes.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/den/UseCaseFactory.h"

namespace sbsim::services {

namespace {

using tinyxml2::XMLAttribute;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

[[noreturn]] void fail(const std::string& source, int line, const std::string& message) {
    throw ServicesConfigError(source + ":" + std::to_string(line) + ": " + message);
}

std::string_view trimmed(std::string_view s) {
    constexpr std::string_view kBlanks = " \t\n\r";
    const std::size_t first = s.find_first_not_of(kBlanks);
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(kBlanks) - first + 1);
}

// The 1-based line of a byte of the text; lines end at '\n', as tinyxml2 counts them.
int lineAt(std::string_view text, std::size_t offset) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

std::string tag(std::string_view name) { return "<" + std::string(name) + ">"; }
std::string tag(const XMLElement& element) { return tag(element.Name()); }

// The element a tinyxml2 error is about: its error string ends in "XMLElement name=<name>" then.
std::string erroneousElement(const XMLDocument& doc) {
    constexpr std::string_view kKey = "XMLElement name=";
    const std::string_view error = doc.ErrorStr();
    const std::size_t at = error.find(kKey);
    return at == std::string_view::npos ? std::string() : std::string(error.substr(at + kKey.size()));
}

// tinyxml2 takes an element whose start tag ends the text for one closed by a mismatched end tag;
// with a blank after the text it reports it as never closed, as it is.
tinyxml2::XMLError parseXml(XMLDocument& doc, std::string_view text) {
    std::string buffer(text);
    buffer += '\n';
    return doc.Parse(buffer.data(), buffer.size());
}

// tinyxml2 reports a mismatched end tag at the start tag left open. The end tag itself is found
// with tinyxml2 too: it reads forward only and stops right after that tag, so a prefix of the
// text shows the mismatch exactly when it holds the whole tag (shorter ones only end too early).
// A binary search over the prefix lengths finds the tag's closing '>'.
[[noreturn]] void failMismatch(const XMLDocument& doc, std::string_view text, const std::string& source) {
    std::size_t clean = 0;             // this long a prefix does not show the mismatch ...
    std::size_t broken = text.size();  // ... and this long one does
    while (broken - clean > 1) {
        const std::size_t length = clean + (broken - clean) / 2;
        XMLDocument prefix;
        (parseXml(prefix, text.substr(0, length)) == tinyxml2::XML_ERROR_MISMATCHED_ELEMENT ? broken : clean) = length;
    }
    const std::size_t start = text.rfind("</", broken);
    const std::string_view rest = text.substr(start + 2, broken - 1 - (start + 2));  // tinyxml2 allows attributes
    const std::string_view name = rest.substr(0, rest.find_first_of(" \t\r\n"));
    fail(source, lineAt(text, start),
         "mismatched end tag </" + std::string(name) + ">, expected </" + erroneousElement(doc) + "> (opened on line " +
             std::to_string(doc.ErrorLineNum()) + ")");
}

// A file tinyxml2 rejects, in words, at the line tinyxml2 names.
[[noreturn]] void failXml(const XMLDocument& doc, std::string_view text, const std::string& source) {
    const int line = doc.ErrorLineNum();
    const std::string element = erroneousElement(doc);
    switch (doc.ErrorID()) {
        case tinyxml2::XML_ERROR_EMPTY_DOCUMENT:
            fail(source, lineAt(text, text.size()), "no root element");
        case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
            failMismatch(doc, text, source);
        case tinyxml2::XML_ERROR_PARSING:
            fail(source, line, "element never closed (or '<' without an element name)");
        case tinyxml2::XML_ERROR_PARSING_ELEMENT:
            if (element.empty())
                fail(source, line, "unexpected character in a tag (expected an attribute, '>' or '/>')");
            fail(source, line, "unterminated tag " + tag(element));
        case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
            fail(source, line,
                 "malformed attribute in " + tag(element) +
                     ": an unterminated quote, a missing '=' or quoted value, or a duplicate attribute");
        case tinyxml2::XML_ERROR_PARSING_TEXT:
            fail(source, line, "text runs to the end of the file (an element never closed, or text after the root)");
        case tinyxml2::XML_ERROR_PARSING_CDATA:
            fail(source, line, "unterminated CDATA section");
        case tinyxml2::XML_ERROR_PARSING_COMMENT:
            fail(source, line, "unterminated comment");
        case tinyxml2::XML_ERROR_PARSING_DECLARATION:
            fail(source, line, "unterminated or misplaced '<?' (the XML declaration belongs at the start of the file)");
        case tinyxml2::XML_ERROR_PARSING_UNKNOWN:
            fail(source, line, "unterminated '<!' declaration");
        case tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED:
            fail(source, line, "elements nested too deeply");
        default:
            fail(source, line, std::string("malformed XML (") + doc.ErrorName() + ")");
    }
}

// tinyxml2 keeps <!DOCTYPE ...> and other declarations as opaque nodes. The format has none, and
// entities declared there would silently not apply, so the first one anywhere is an error.
class FirstDeclaration : public tinyxml2::XMLVisitor {
public:
    bool Visit(const tinyxml2::XMLUnknown& node) override {
        if (!found) found = &node;
        return false;
    }
    const tinyxml2::XMLUnknown* found = nullptr;
};

// tinyxml2 accepts text and several elements at the top; a well-formed file has one root element.
const XMLElement& rootOf(const XMLDocument& doc, std::string_view text, const std::string& source) {
    FirstDeclaration declaration;
    doc.Accept(&declaration);
    if (declaration.found) {
        const std::string_view value = declaration.found->Value();
        fail(source, declaration.found->GetLineNum(),
             "unsupported declaration <!" + std::string(value.substr(0, value.find_first_of(" \t\r\n"))) + " ...>");
    }
    const XMLElement* root = nullptr;
    for (const XMLNode* node = doc.FirstChild(); node; node = node->NextSibling()) {
        if (node->ToComment() || node->ToDeclaration()) continue;
        if (root) fail(source, node->GetLineNum(), "unexpected content after the root element " + tag(*root));
        if (!node->ToElement()) fail(source, node->GetLineNum(), "expected the root element, found text");
        root = node->ToElement();
    }
    if (!root) fail(source, lineAt(text, text.size()), "no root element");
    return *root;
}

// Character data where the format has none is most likely a misplaced value: say so.
void rejectText(const XMLElement& element, const std::string& source) {
    for (const XMLNode* node = element.FirstChild(); node; node = node->NextSibling()) {
        const tinyxml2::XMLText* text = node->ToText();
        if (text && !trimmed(text->Value()).empty()) {
            fail(source, element.GetLineNum(), "unexpected text in " + tag(element));
        }
    }
}

// The element's attributes in document order, with XML's attribute-value normalization, which
// tinyxml2 leaves out: literal tabs and line ends become spaces (so a value quoted in a message
// keeps it one line).
std::vector<std::pair<std::string, std::string>> attributesOf(const XMLElement& element) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const XMLAttribute* attribute = element.FirstAttribute(); attribute; attribute = attribute->Next()) {
        std::string value = attribute->Value();
        std::replace_if(
            value.begin(), value.end(), [](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
        out.emplace_back(attribute->Name(), std::move(value));
    }
    return out;
}

void rejectAttributes(const XMLElement& element, const std::string& source) {
    if (const XMLAttribute* first = element.FirstAttribute()) {
        fail(source, element.GetLineNum(),
             "unexpected attribute '" + std::string(first->Name()) + "' on " + tag(element));
    }
}

ServiceFilter parseFilter(const XMLElement& element, const std::string& source) {
    const std::string_view name = element.Name();
    const int line = element.GetLineNum();
    ServiceFilter filter;
    filter.line = line;
    filter.subject = name == "type" ? ServiceFilter::Subject::VehicleType : ServiceFilter::Subject::VehicleId;
    bool hasPattern = false;
    for (const auto& [key, value] : attributesOf(element)) {
        if (key == "pattern") {
            filter.pattern = value;
            hasPattern = true;
        } else if (key == "match") {
            if (value != "inverse") {
                fail(source, line,
                     "unknown match '" + value + "' in " + tag(name) + " filter (the only value is 'inverse')");
            }
            filter.inverse = true;
        } else if (key == "rate") {
            // Artery draws a random number per vehicle here; we have no random stream for it (yet).
            fail(source, line, "the 'rate' attribute of " + tag(name) + " filters is not supported");
        } else {
            fail(source, line, "unexpected attribute '" + key + "' on " + tag(name) + " filter");
        }
    }
    if (!hasPattern) fail(source, line, tag(name) + " filter has no 'pattern' attribute");
    if (filter.pattern.size() > ServiceFilter::kMaxPatternLength) {
        fail(source, line,
             fmt::format("the pattern of {} filter is {} characters long (at most {})", tag(name),
                         filter.pattern.size(), ServiceFilter::kMaxPatternLength));
    }
    RE2::Options options;
    options.set_log_errors(false);  // the error goes into our one line instead
    auto regex = std::make_shared<const RE2>(filter.pattern, options);
    if (!regex->ok()) {
        fail(source, line, "invalid pattern '" + filter.pattern + "' in " + tag(name) + " filter: " + regex->error());
    }
    filter.regex = std::move(regex);
    rejectText(element, source);
    return filter;
}

ServiceSpec::Equipment parseEquipment(const XMLElement& element, const std::string& source) {
    auto equipment = ServiceSpec::Equipment::Equipped;
    for (const auto& [key, value] : attributesOf(element)) {
        if (key != "match") fail(source, element.GetLineNum(), "unexpected attribute '" + key + "' on <equipped>");
        if (value == "inverse") {
            equipment = ServiceSpec::Equipment::Unequipped;
        } else if (value == "any") {
            equipment = ServiceSpec::Equipment::Any;
        } else {
            fail(source, element.GetLineNum(),
                 "unknown match '" + value + "' in <equipped> filter (expected 'inverse' or 'any')");
        }
    }
    rejectText(element, source);
    return equipment;
}

void parseFilters(const XMLElement& element, const std::string& source, ServiceSpec& spec) {
    for (const auto& [key, value] : attributesOf(element)) {
        if (key != "operator") fail(source, element.GetLineNum(), "unexpected attribute '" + key + "' on <filters>");
        if (value == "and") {
            spec.combine = ServiceSpec::Combine::All;
        } else if (value == "or") {
            spec.combine = ServiceSpec::Combine::Any;
        } else {
            fail(source, element.GetLineNum(), "unknown filter operator '" + value + "' (expected 'and' or 'or')");
        }
    }
    rejectText(element, source);
    for (const XMLElement* child = element.FirstChildElement(); child; child = child->NextSiblingElement()) {
        const std::string_view name = child->Name();
        if (name == "name" || name == "type") {
            spec.filters.push_back(parseFilter(*child, source));
        } else if (name == "equipped") {
            spec.equipment = parseEquipment(*child, source);
        } else if (name == "penetration") {
            fail(source, child->GetLineNum(),
                 "Artery's <penetration> filter is not supported: run sbsim with --penetration (and <equipped> "
                 "filters)");
        } else {
            fail(source, child->GetLineNum(),
                 "unknown filter " + tag(name) + " (expected <name>, <type> or <equipped>)");
        }
    }
}

// Artery's module names ("artery.application.CaService", "artery.application.den.TractionLoss")
// name sbsim's services and use cases of the same short name.
std::string shortTypeName(std::string_view type) {
    for (const std::string_view prefix : {"artery.application.den.", "artery.application."}) {
        if (type.substr(0, prefix.size()) == prefix) return std::string(type.substr(prefix.size()));
    }
    return std::string(type);
}

// Artery-only elements met while reading one file, for the one line that says they were ignored.
struct Ignored {
    std::vector<std::string> names;
    void add(std::string_view name) {
        if (std::find(names.begin(), names.end(), name) == names.end()) names.emplace_back(name);
    }
};

ServiceSpec parseService(const XMLElement& element, const std::string& source, Ignored& ignored,
                         std::string_view elementName = "service") {
    ServiceSpec spec;
    spec.source = source;
    spec.line = element.GetLineNum();
    const auto attributes = attributesOf(element);
    const auto type =
        std::find_if(attributes.begin(), attributes.end(), [](const auto& a) { return a.first == "type"; });
    if (type == attributes.end()) fail(source, spec.line, tag(elementName) + " has no 'type' attribute");
    if (trimmed(type->second).empty()) fail(source, spec.line, tag(elementName) + " has an empty 'type' attribute");
    spec.writtenType = type->second;
    spec.type = shortTypeName(type->second);
    for (const auto& [key, value] : attributes) {
        if (key != "type") spec.parameters.emplace(key, value);
    }
    rejectText(element, source);
    bool hasFilters = false;
    for (const XMLElement* child = element.FirstChildElement(); child; child = child->NextSiblingElement()) {
        const std::string_view name = child->Name();
        if (name == "listener") {  // Artery's port binding; services here talk in-process
            ignored.add(name);
            continue;
        }
        if (name != "filters") {
            fail(source, child->GetLineNum(),
                 "unexpected element " + tag(name) + " in " + tag(elementName) + " (expected <filters> or <listener>)");
        }
        if (hasFilters) fail(source, child->GetLineNum(), "a " + tag(elementName) + " may have only one <filters>");
        hasFilters = true;
        parseFilters(*child, source, spec);
    }
    return spec;
}

// A coordinate attribute: a number on the map (no network is wider than 10,000 km; the units'
// grid and the distances squared stay finite).
constexpr double kMaxCoordinate = 1e7;
double coordinate(const std::string& value, std::string_view name, const std::string& source, int line) {
    const std::string_view text = trimmed(value);
    double out = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !(std::abs(out) <= kMaxCoordinate)) {
        fail(source, line,
             fmt::format("attribute '{}' of <rsu> must be a number from {:g} to {:g} m, got '{}'", name,
                         -kMaxCoordinate, kMaxCoordinate, value));
    }
    return out;
}

// <rsu id x y> or <rsu poiType>, with its <service> children (no filters: they run on the unit).
RoadsideUnitSpec parseRoadsideUnit(const XMLElement& element, const std::string& source, Ignored& ignored) {
    RoadsideUnitSpec rsu;
    rsu.source = source;
    rsu.line = element.GetLineNum();
    std::optional<double> x, y;
    bool hasId = false;
    for (const auto& [key, value] : attributesOf(element)) {
        if (key == "id") {
            if (trimmed(value).empty()) fail(source, rsu.line, "<rsu> has an empty 'id'");
            rsu.id = value;
            hasId = true;
        } else if (key == "x") {
            x = coordinate(value, key, source, rsu.line);
        } else if (key == "y") {
            y = coordinate(value, key, source, rsu.line);
        } else if (key == "poiType") {
            if (trimmed(value).empty()) fail(source, rsu.line, "<rsu> has an empty 'poiType'");
            rsu.poiType = value;
        } else {
            fail(source, rsu.line, "unexpected attribute '" + key + "' on <rsu> (expected id, x and y, or poiType)");
        }
    }
    if (rsu.poiType) {
        if (hasId || x || y)
            fail(source, rsu.line, "an <rsu> with 'poiType' takes its id and position from each POI: no id, x or y");
    } else if (!hasId || !x || !y) {
        fail(source, rsu.line, "an <rsu> needs 'id', 'x' and 'y' (or 'poiType' for every SUMO POI of that type)");
    } else {
        rsu.x = *x;
        rsu.y = *y;
    }
    rejectText(element, source);
    for (const XMLElement* child = element.FirstChildElement(); child; child = child->NextSiblingElement()) {
        if (std::string_view(child->Name()) != "service") {
            fail(source, child->GetLineNum(), "unexpected element " + tag(*child) + " in <rsu> (expected <service>)");
        }
        ServiceSpec spec = parseService(*child, source, ignored);
        if (!spec.filters.empty() || spec.equipment != ServiceSpec::Equipment::Equipped)
            fail(source, spec.line, "a roadside unit's <service> takes no <filters>: it runs on the unit");
        rsu.services.push_back(std::move(spec));
    }
    if (rsu.services.empty()) fail(source, rsu.line, "<rsu> has no <service>");
    return rsu;
}

// A file's elements under its root `rootName`, each a `childName` read like a <service>; with
// `roadsideUnits`, <rsu> elements too.
std::vector<ServiceSpec> readSpecs(std::string_view text, const std::string& source, std::string_view rootName,
                                   std::string_view childName, std::vector<RoadsideUnitSpec>* roadsideUnits = nullptr) {
    // tinyxml2 reads a C string: a NUL byte would silently end the file there.
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
        fail(source, lineAt(text, nul), "NUL character in the file");
    }
    XMLDocument doc;
    if (parseXml(doc, text) != tinyxml2::XML_SUCCESS) failXml(doc, text, source);
    const XMLElement& root = rootOf(doc, text, source);
    if (std::string_view(root.Name()) != rootName) {
        fail(source, root.GetLineNum(), "the root element must be " + tag(rootName) + ", found " + tag(root));
    }
    rejectAttributes(root, source);
    rejectText(root, source);
    std::vector<ServiceSpec> out;
    Ignored ignored;
    for (const XMLElement* child = root.FirstChildElement(); child; child = child->NextSiblingElement()) {
        if (roadsideUnits != nullptr && std::string_view(child->Name()) == "rsu") {
            RoadsideUnitSpec rsu = parseRoadsideUnit(*child, source, ignored);
            for (const RoadsideUnitSpec& other : *roadsideUnits) {
                if (!rsu.id.empty() && other.id == rsu.id)
                    fail(source, rsu.line, "two roadside units are called '" + rsu.id + "'");
            }
            roadsideUnits->push_back(std::move(rsu));
            continue;
        }
        if (std::string_view(child->Name()) != childName) {
            fail(source, child->GetLineNum(),
                 "unexpected element " + tag(*child) + " in " + tag(rootName) + " (expected " + tag(childName) +
                     (roadsideUnits != nullptr ? " or <rsu>)" : ")"));
        }
        out.push_back(parseService(*child, source, ignored, childName));
    }
    if (!ignored.names.empty()) {
        std::string list;
        for (const std::string& n : ignored.names) list += (list.empty() ? "" : ", ") + tag(n);
        std::fprintf(stderr, "sbsim: note: %s: Artery's %s ignored (services here talk in-process)\n", source.c_str(),
                     list.c_str());
    }
    return out;
}

std::string readFile(const std::filesystem::path& path) {
    const std::string source = path.string();
    std::error_code ec;
    // Refused before it is opened: an ifstream opens a directory without complaint and then reads
    // nothing, and opening a FIFO blocks until a writer comes, which may be never.
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw ServicesConfigError(source + ": cannot read: not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ServicesConfigError(source + ": cannot read");
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw ServicesConfigError(source + ": cannot read");
    return text;
}

// The use cases of a service that runs them (a DenService): its `useCases` file (relative to the services file), else
// den-use-cases.xml beside the services file, else none listed (all run).
void attachUseCases(ServiceSpec& spec, std::vector<std::filesystem::path>& files) {
    const std::filesystem::path dir = std::filesystem::path(spec.source).parent_path();
    std::filesystem::path file;
    if (const auto named = spec.parameter("useCases")) {
        file = dir / *named;
    } else {
        std::error_code ec;
        if (!std::filesystem::exists(dir / "den-use-cases.xml", ec)) return;
        file = dir / "den-use-cases.xml";
    }
    if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
    auto useCases = readSpecs(readFile(file), file.string(), "usecases", "usecase");
    for (const ServiceSpec& u : useCases) {
        if (!isUseCase(u.type)) {
            try {
                (void)makeUseCase(u.type);
            } catch (const std::out_of_range& e) {
                fail(u.source, u.line, e.what());
            }
        }
    }
    for (const ServiceSpec& u : useCases) {
        checkAttributes(u);
        const auto signal = u.parameter("signal");
        if (u.type == "StoryboardEvent" && (!signal || trimmed(*signal).empty()))
            fail(u.source, u.line, "the StoryboardEvent use case needs a 'signal' attribute");
    }
    spec.useCases = std::make_shared<const std::vector<ServiceSpec>>(std::move(useCases));
}

std::vector<ServiceSpec> readServices(std::string_view text, const std::string& source,
                                      std::vector<RoadsideUnitSpec>& roadsideUnits,
                                      std::vector<std::filesystem::path>& files) {
    std::vector<ServiceSpec> out = readSpecs(text, source, "services", "service", &roadsideUnits);
    for (const ServiceSpec& spec : out) checkAttributes(spec);
    for (const RoadsideUnitSpec& rsu : roadsideUnits) {
        for (const ServiceSpec& spec : rsu.services) checkAttributes(spec);
    }
    for (ServiceSpec& spec : out) {
        if (ServiceRegistry::instance().traits(spec.type).runsUseCases) attachUseCases(spec, files);
    }
    return out;
}

}  // namespace

bool ServiceFilter::matches(std::string_view vehicleId, std::string_view vehicleType) const {
    const std::string_view subjectText = subject == Subject::VehicleId ? vehicleId : vehicleType;
    return RE2::FullMatch(re2::StringPiece(subjectText.data(), subjectText.size()), *regex) != inverse;
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

kernel::SimTime ServiceSpec::duration(std::string_view name, double fallback) const {
    const double seconds = number(name, fallback);
    if (!(seconds >= kMinDurationSeconds && seconds <= kMaxDurationSeconds)) {
        const std::string bounds =
            fmt::format("a duration from {:g} to {:g} s", kMinDurationSeconds, kMaxDurationSeconds);
        if (parameters.find(name) != parameters.end()) badParameter(name, bounds);
        fail(source, line,
             fmt::format("parameter '{}' of service '{}' must be {}; unset, it is {:g} s here: set it", name, type,
                         bounds, seconds));
    }
    return kernel::SimTime::fromSeconds(seconds);
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
    config.services_ = readServices(text, source, config.roadsideUnits_, config.otherFiles_);
    return config;
}

ServicesConfig ServicesConfig::load(const std::filesystem::path& path) { return parse(readFile(path), path.string()); }

std::vector<const ServiceSpec*> ServicesConfig::allServices() const {
    std::vector<const ServiceSpec*> out;
    for (const ServiceSpec& spec : services_) out.push_back(&spec);
    for (const RoadsideUnitSpec& rsu : roadsideUnits_) {
        for (const ServiceSpec& spec : rsu.services) out.push_back(&spec);
    }
    return out;
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
