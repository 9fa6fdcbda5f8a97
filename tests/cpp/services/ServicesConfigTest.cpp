#include "sbsim/services/ServicesConfig.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sbsim/services/Service.h"
#include "sbsim/services/ServiceRegistry.h"

namespace sbsim::services {
namespace {

ServicesConfig parse(std::string_view text) { return ServicesConfig::parse(text, "s.xml"); }

// The message ServicesConfig::parse gives for `text` (source "s.xml"), or "no error".
std::string errorOf(std::string_view text) {
    try {
        parse(text);
    } catch (const ServicesConfigError& e) {
        return e.what();
    }
    return "no error";
}

// A <services> document with one service whose body is `body`; the service starts on line 2.
std::string oneService(std::string_view body, std::string_view attributes = "type=\"S\"") {
    return "<services>\n<service " + std::string(attributes) + ">\n" + std::string(body) + "</service>\n</services>\n";
}

// The config's one service; a reference into `config`, so copy it when `config` is a temporary.
const ServiceSpec& onlyService(const ServicesConfig& config) {
    EXPECT_EQ(config.services().size(), 1u);
    return config.services().at(0);
}

// Artery's scenarios/artery/services.xml layout (tabs, XML declaration, listeners), plus a comment.
constexpr std::string_view kArteryExample =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<services>\n"
    "\t<!-- every vehicle except persons runs the CA service -->\n"
    "\t<service type=\"artery.application.CaService\">\n"
    "\t\t<listener port=\"2001\" />\n"
    "\t\t<filters>\n"
    "\t\t\t<type pattern=\"artery.inet.Person\" match=\"inverse\" />\n"
    "\t\t</filters>\n"
    "\t</service>\n"
    "\t<service type=\"artery.application.ExampleService\" name=\"Example\">\n"
    "\t\t<listener port=\"4711\" />\n"
    "\t\t<filters>\n"
    "\t\t\t<name pattern=\"flow0\\.1.*\" />\n"
    "\t\t</filters>\n"
    "\t</service>\n"
    "\t<service type=\"artery.application.DenService\">\n"
    "\t\t<listener port=\"2002\" />\n"
    "\t</service>\n"
    "</services>\n";

TEST(ServicesConfig, ArteryExample) {
    const ServicesConfig config = parse(kArteryExample);
    const auto& services = config.services();
    ASSERT_EQ(services.size(), 3u);

    // Artery's module name names sbsim's service of the same short name.
    EXPECT_EQ(services[0].type, "CaService");
    EXPECT_EQ(services[0].writtenType, "artery.application.CaService");
    EXPECT_EQ(services[0].line, 4);
    EXPECT_EQ(services[0].source, "s.xml");
    EXPECT_TRUE(services[0].parameters.empty());
    ASSERT_EQ(services[0].filters.size(), 1u);
    EXPECT_EQ(services[0].filters[0].subject, ServiceFilter::Subject::VehicleType);
    EXPECT_EQ(services[0].filters[0].pattern, "artery.inet.Person");
    EXPECT_TRUE(services[0].filters[0].inverse);
    EXPECT_EQ(services[0].filters[0].line, 7);
    EXPECT_TRUE(services[0].matches("flow0.1", "passenger"));
    EXPECT_FALSE(services[0].matches("walker", "artery.inet.Person"));

    // Artery's module name names sbsim's service of the same short name.
    EXPECT_EQ(services[1].type, "ExampleService");
    EXPECT_EQ(services[1].writtenType, "artery.application.ExampleService");
    EXPECT_EQ(services[1].parameter("name"), "Example");
    EXPECT_TRUE(services[1].matches("flow0.1", "car"));
    EXPECT_TRUE(services[1].matches("flow0.12", "car"));
    EXPECT_FALSE(services[1].matches("flow0.2", "car"));
    EXPECT_FALSE(services[1].matches("flow001", "car"));  // the escaped dot is literal

    // Artery's module name names sbsim's service of the same short name.
    EXPECT_EQ(services[2].type, "DenService");
    EXPECT_EQ(services[2].writtenType, "artery.application.DenService");
    EXPECT_TRUE(services[2].filters.empty());
    EXPECT_TRUE(services[2].matches("anything", ""));
}

TEST(ServicesConfig, EmptyServicesAndDefaultConfig) {
    EXPECT_TRUE(parse("<services/>").services().empty());
    EXPECT_TRUE(parse("<services>\n  <!-- nothing yet -->\n</services>").services().empty());
    EXPECT_TRUE(ServicesConfig().services().empty());
}

TEST(ServicesConfig, ParametersAreAllAttributesButType) {
    const ServicesConfig config = parse(oneService("", R"(interval="0.5" type="PluginService" range="300")"));
    const ServiceSpec& spec = onlyService(config);
    EXPECT_EQ(spec.type, "PluginService");
    EXPECT_EQ(spec.parameters.size(), 2u);
    EXPECT_EQ(spec.parameter("interval"), "0.5");
    EXPECT_EQ(spec.parameter("range"), "300");
    EXPECT_EQ(spec.parameter("type"), std::nullopt);
    EXPECT_EQ(spec.parameter("missing"), std::nullopt);
}

TEST(ServicesConfig, ParameterValuesAreEntityDecoded) {
    const ServiceSpec spec = onlyService(parse(oneService("", R"(type="S" cause="a &amp; b &lt;3")")));
    EXPECT_EQ(spec.parameter("cause"), "a & b <3");
}

TEST(ServicesConfig, AttributeQuotingAndCharacterReferences) {
    const ServiceSpec spec = onlyService(parse(oneService(
        "",
        R"(type='S' single='say "hi"' double="it's" named="&lt;&gt;&amp;&quot;&apos;" numeric="&#65;&#x42;&#x20AC;")")));
    EXPECT_EQ(spec.type, "S");
    EXPECT_EQ(spec.parameter("single"), "say \"hi\"");
    EXPECT_EQ(spec.parameter("double"), "it's");
    EXPECT_EQ(spec.parameter("named"), "<>&\"'");
    EXPECT_EQ(spec.parameter("numeric"), "AB\xE2\x82\xAC");
    // Patterns are decoded before they are compiled.
    const ServiceSpec filtered =
        onlyService(parse(oneService(R"(<filters><name pattern="a&amp;b|&#x63;"/></filters>)")));
    EXPECT_TRUE(filtered.matches("a&b", ""));
    EXPECT_TRUE(filtered.matches("c", ""));
    EXPECT_FALSE(filtered.matches("a&amp;b", ""));
}

TEST(ServicesConfig, AttributeWhitespaceIsNormalized) {
    const ServiceSpec spec = onlyService(parse(oneService("", "type=\"S\" cause=\"x\ny\tz\r\nw\"")));
    EXPECT_EQ(spec.parameter("cause"), "x y z w");
    // ... so that a message quoting a value stays one line.
    EXPECT_EQ(errorOf(oneService("<filters operator='a\nnd'/>\n")),
              "s.xml:3: unknown filter operator 'a nd' (expected 'and' or 'or')");
}

TEST(ServicesConfig, ByteOrderMarkDeclarationCommentsAndBlankCData) {
    const ServicesConfig config = parse(
        "\xEF\xBB\xBF<?xml version='1.0' encoding='UTF-8'?><?style x?>\n"
        "<!-- before the root -->\n"
        "<services><!-- a - b -->\n"
        "  <service type=\"S\"><![CDATA[  ]]><!-- inside -->\n"
        "    <filters><!---->\n"
        "      <name pattern=\"x\"/><!-- after -->\n"
        "    </filters>\n"
        "  </service>\n"
        "</services>\n"
        "<!-- after the root -->\n");
    const ServiceSpec& spec = onlyService(config);
    EXPECT_EQ(spec.line, 4);
    ASSERT_EQ(spec.filters.size(), 1u);
    EXPECT_EQ(spec.filters[0].line, 6);
}

TEST(ServicesConfig, LinesAreThoseOfTheStartTags) {
    const ServicesConfig config = parse(
        "<services\n"
        ">\n"
        "  <service\n"
        "      type=\"A\"\n"
        "      range=\"x\">\n"
        "    <listener port=\"1\"><nested><deeper/></nested></listener>\n"
        "    <filters\n"
        "        operator=\"and\">\n"
        "      <name pattern=\"a\"/><type\n"
        "        pattern=\"b\"/>\n"
        "    </filters>\n"
        "  </service><service type=\"B\"/>\n"
        "</services>\n");
    const auto& services = config.services();
    ASSERT_EQ(services.size(), 2u);
    EXPECT_EQ(services[0].line, 3);
    ASSERT_EQ(services[0].filters.size(), 2u);
    EXPECT_EQ(services[0].filters[0].line, 9);
    EXPECT_EQ(services[0].filters[1].line, 9);
    EXPECT_EQ(services[1].line, 12);
    try {
        services[0].number("range", 0);
        FAIL() << "no error";
    } catch (const ServicesConfigError& e) {
        EXPECT_EQ(std::string(e.what()), "s.xml:3: parameter 'range' of service 'A' must be a number, got 'x'");
    }
}

TEST(ServicesConfig, NumberParameters) {
    const ServicesConfig config = parse(oneService("", R"(type="S" a="0.5" b=" 300 " c="-2e3" d="+7" e=".25" i="10")"));
    const ServiceSpec& spec = onlyService(config);
    EXPECT_DOUBLE_EQ(spec.number("a", 0), 0.5);
    EXPECT_DOUBLE_EQ(spec.number("b", 0), 300);
    EXPECT_DOUBLE_EQ(spec.number("c", 0), -2000);
    EXPECT_DOUBLE_EQ(spec.number("d", 0), 7);
    EXPECT_DOUBLE_EQ(spec.number("e", 0), 0.25);
    EXPECT_DOUBLE_EQ(spec.number("i", 0), 10);
    EXPECT_DOUBLE_EQ(spec.number("missing", 42.5), 42.5);
}

TEST(ServicesConfig, DurationsHaveBounds) {
    // 1e-12 s passed a "> 0" check, rounded to 0 ns and fired at one instant for ever.
    const ServicesConfig config =
        parse(oneService("", R"(type="S" a="0.5" tiny="1e-12" zero="0" negative="-1" huge="1e300" edge="0.001")"));
    const ServiceSpec& spec = onlyService(config);
    EXPECT_EQ(spec.duration("a", 1), kernel::SimTime::fromMilliseconds(500));
    EXPECT_EQ(spec.duration("edge", 1), kernel::SimTime::fromMilliseconds(1));
    EXPECT_EQ(spec.duration("missing", 2), kernel::SimTime::fromSeconds(2));
    for (const std::string name : {"tiny", "zero", "negative", "huge"}) {
        try {
            (void)spec.duration(name, 1);
            ADD_FAILURE() << name << ": no error";
        } catch (const ServicesConfigError& e) {
            EXPECT_EQ(std::string(e.what()), "s.xml:2: parameter '" + name +
                                                 "' of service 'S' must be a duration from 0.001 to 1e+09 s, got '" +
                                                 *spec.parameter(name) + "'");
        }
    }
    EXPECT_THROW((void)spec.duration("missing", 1e-6), ServicesConfigError) << "a default out of bounds too";
}

TEST(ServicesConfig, MalformedNumberNamesFileLineServiceAndText) {
    const ServicesConfig config = parse(
        "<services>\n\n"
        "  <service type=\"T\" x=\"abc\" y=\"\" z=\"1.5m\" w=\"inf\" v=\"nan\" u=\"1e999\" t=\"++1\" s=\"0x10\"/>\n"
        "</services>\n");
    const ServiceSpec& spec = onlyService(config);
    for (const std::string name : {"x", "y", "z", "w", "v", "u", "t", "s"}) {
        try {
            spec.number(name, 0);
            ADD_FAILURE() << name << ": no error";
        } catch (const ServicesConfigError& e) {
            const std::string expected = "s.xml:3: parameter '" + name + "' of service 'T' must be a number, got '" +
                                         *spec.parameter(name) + "'";
            EXPECT_EQ(std::string(e.what()), expected);
        }
    }
}

TEST(ServicesConfig, BooleanParameters) {
    const ServiceSpec spec = onlyService(parse(oneService("", R"(type="T" a="true" b="0" c=" false " d="yes")")));
    EXPECT_TRUE(spec.boolean("a", false));
    EXPECT_FALSE(spec.boolean("b", true));
    EXPECT_FALSE(spec.boolean("c", true));
    EXPECT_TRUE(spec.boolean("missing", true));
    try {
        spec.boolean("d", false);
        FAIL() << "no error";
    } catch (const ServicesConfigError& e) {
        EXPECT_EQ(std::string(e.what()), "s.xml:2: parameter 'd' of service 'T' must be true or false, got 'yes'");
    }
}

TEST(ServicesConfigFilters, NameFilterMustMatchTheWholeId) {
    const ServiceSpec spec = onlyService(parse(oneService(R"(<filters><name pattern="police\d+"/></filters>)")));
    ASSERT_EQ(spec.filters.size(), 1u);
    EXPECT_EQ(spec.filters[0].subject, ServiceFilter::Subject::VehicleId);
    EXPECT_FALSE(spec.filters[0].inverse);
    EXPECT_TRUE(spec.matches("police1", "car"));
    EXPECT_TRUE(spec.matches("police42", "truck"));
    EXPECT_FALSE(spec.matches("police", "car"));
    EXPECT_FALSE(spec.matches("police1x", "car"));
    EXPECT_FALSE(spec.matches("xpolice1", "car"));
    EXPECT_FALSE(spec.matches("", "police1"));  // the type is not looked at
}

TEST(ServicesConfigFilters, TypeFilterLooksAtTheVehicleType) {
    const ServiceSpec spec = onlyService(parse(oneService(R"(<filters><type pattern="truck|bus"/></filters>)")));
    EXPECT_TRUE(spec.matches("v1", "truck"));
    EXPECT_TRUE(spec.matches("v1", "bus"));
    EXPECT_FALSE(spec.matches("v1", "trucks"));
    EXPECT_FALSE(spec.matches("truck", "car"));
}

TEST(ServicesConfigFilters, InverseNegatesOneFilter) {
    const ServiceSpec spec =
        onlyService(parse(oneService(R"(<filters><name pattern="veh1" match="inverse"/></filters>)")));
    EXPECT_TRUE(spec.filters.at(0).inverse);
    EXPECT_FALSE(spec.matches("veh1", "car"));
    EXPECT_TRUE(spec.matches("veh10", "car"));
    EXPECT_TRUE(spec.matches("veh", "car"));
}

TEST(ServicesConfigFilters, AnyFilterPassesByDefaultAsInArtery) {
    const ServiceSpec spec = onlyService(
        parse(oneService("<filters><name pattern=\"police\\d+\"/><type pattern=\"ambulance\"/></filters>")));
    EXPECT_EQ(spec.combine, ServiceSpec::Combine::Any);
    EXPECT_TRUE(spec.matches("police3", "car"));
    EXPECT_TRUE(spec.matches("veh3", "ambulance"));
    EXPECT_FALSE(spec.matches("veh3", "car"));
}

TEST(ServicesConfigFilters, AndOperatorNeedsAllFilters) {
    const ServiceSpec spec =
        onlyService(parse(oneService("<filters operator=\"and\">\n"
                                     "  <name pattern=\"police\\d+\"/>\n"
                                     "  <name pattern=\"police1\" match=\"inverse\"/>\n"
                                     "  <type pattern=\"truck|bus\"/>\n"
                                     "</filters>\n")));
    EXPECT_EQ(spec.combine, ServiceSpec::Combine::All);
    ASSERT_EQ(spec.filters.size(), 3u);
    EXPECT_EQ(spec.filters[2].line, 6);
    EXPECT_TRUE(spec.matches("police2", "bus"));
    EXPECT_FALSE(spec.matches("police1", "bus"));  // the inverse filter fails
    EXPECT_FALSE(spec.matches("police2", "car"));  // the type filter fails
    EXPECT_FALSE(spec.matches("veh2", "bus"));     // the first name filter fails
}

TEST(ServicesConfigFilters, ExplicitAndOperator) {
    const ServiceSpec spec = onlyService(
        parse(oneService(R"(<filters operator="and"><name pattern="a.*"/><type pattern="bus"/></filters>)")));
    EXPECT_EQ(spec.combine, ServiceSpec::Combine::All);
    EXPECT_TRUE(spec.matches("a1", "bus"));
    EXPECT_FALSE(spec.matches("a1", "car"));
}

TEST(ServicesConfigFilters, OrOperatorNeedsOnePassingFilter) {
    const ServiceSpec spec = onlyService(parse(oneService(
        R"(<filters operator="or"><name pattern="police\d+"/><type pattern="ambulance"/>
           <name pattern=".*" match="inverse"/></filters>)")));
    EXPECT_EQ(spec.combine, ServiceSpec::Combine::Any);
    EXPECT_TRUE(spec.matches("police3", "car"));
    EXPECT_TRUE(spec.matches("veh3", "ambulance"));
    EXPECT_TRUE(spec.matches("police3", "ambulance"));
    EXPECT_FALSE(spec.matches("veh3", "car"));
}

TEST(ServicesConfigFilters, NoFiltersOrEmptyFiltersSelectEveryVehicle) {
    for (const std::string body : {"", "<filters/>", "<filters operator=\"or\"></filters>"}) {
        const ServiceSpec spec = onlyService(parse(oneService(body)));
        EXPECT_TRUE(spec.filters.empty()) << body;
        EXPECT_TRUE(spec.matches("v", "t")) << body;
        EXPECT_TRUE(spec.matches("", "")) << body;
    }
}

TEST(ServicesConfigFilters, MatchingListsServicesInFileOrder) {
    const ServicesConfig config = parse(
        "<services>\n"
        "  <service type=\"A\"><filters><name pattern=\"p.*\"/></filters></service>\n"
        "  <service type=\"B\"/>\n"
        "  <service type=\"C\"><filters><type pattern=\"bus\"/></filters></service>\n"
        "  <service type=\"A\" variant=\"2\"/>\n"
        "</services>\n");
    const auto types = [&](std::string_view id, std::string_view type) {
        std::string out;
        for (const ServiceSpec* spec : config.matching(id, type)) out += spec->type;
        return out;
    };
    EXPECT_EQ(types("p1", "bus"), "ABCA");
    EXPECT_EQ(types("v1", "car"), "BA");
}

TEST(ServicesConfigFilters, CopiesAndMovesKeepWorkingRegexes) {
    ServicesConfig original = parse(oneService(R"(<filters><name pattern="x\d"/></filters>)"));
    const ServicesConfig copy = original;
    const ServicesConfig moved = std::move(original);
    EXPECT_TRUE(onlyService(copy).matches("x1", ""));
    EXPECT_FALSE(onlyService(moved).matches("x", ""));
    EXPECT_TRUE(onlyService(moved).matches("x2", ""));
}

// --- errors ---

TEST(ServicesConfigErrors, WrongRoot) {
    EXPECT_EQ(errorOf("<?xml version='1.0'?>\n<service type='S'/>"),
              "s.xml:2: the root element must be <services>, found <service>");
    EXPECT_EQ(errorOf("<services version='1'/>"), "s.xml:1: unexpected attribute 'version' on <services>");
    EXPECT_EQ(errorOf("<services>\nCaService\n</services>"), "s.xml:1: unexpected text in <services>");
}

TEST(ServicesConfigErrors, UnknownElements) {
    EXPECT_EQ(errorOf("<services>\n  <service type='S'/>\n  <servce type='T'/>\n</services>"),
              "s.xml:3: unexpected element <servce> in <services> (expected <service> or <rsu>)");
    EXPECT_EQ(errorOf(oneService("<listener port='1'/>\n<filter/>\n")),
              "s.xml:4: unexpected element <filter> in <service> (expected <filters> or <listener>)");
    EXPECT_EQ(errorOf(oneService("<filters/>\n<filters/>\n")), "s.xml:4: a <service> may have only one <filters>");
    EXPECT_EQ(errorOf(oneService("interval\n")), "s.xml:2: unexpected text in <service>");
}

TEST(ServicesConfigErrors, MissingOrEmptyType) {
    EXPECT_EQ(errorOf("<services>\n\n<service interval='1'/>\n</services>"),
              "s.xml:3: <service> has no 'type' attribute");
    EXPECT_EQ(errorOf("<services>\n<service type=' '/>\n</services>"),
              "s.xml:2: <service> has an empty 'type' attribute");
}

TEST(ServicesConfigErrors, UnknownFilter) {
    EXPECT_EQ(errorOf(oneService("<filters>\n  <name pattern='a'/>\n  <speed max='3'/>\n</filters>\n")),
              "s.xml:5: unknown filter <speed> (expected <name>, <type> or <equipped>)");
}

TEST(ServicesConfigErrors, ArteryRandomFiltersAreRejected) {
    EXPECT_EQ(errorOf(oneService("<filters>\n<penetration rate='0.1'/>\n</filters>\n")),
              "s.xml:4: Artery's <penetration> filter is not supported: run sbsim with --penetration (and <equipped> "
              "filters)");
    EXPECT_EQ(errorOf(oneService("<filters>\n<type pattern='car' rate='0.5'/>\n</filters>\n")),
              "s.xml:4: the 'rate' attribute of <type> filters is not supported");
}

TEST(ServicesConfigErrors, MissingPattern) {
    EXPECT_EQ(errorOf(oneService("<filters>\n<name/>\n</filters>\n")),
              "s.xml:4: <name> filter has no 'pattern' attribute");
    EXPECT_EQ(errorOf(oneService("<filters>\n\n<type match='inverse'/>\n</filters>\n")),
              "s.xml:5: <type> filter has no 'pattern' attribute");
}

TEST(ServicesConfigErrors, UnknownMatchOrAttribute) {
    EXPECT_EQ(errorOf(oneService("<filters>\n<name pattern='a' match='inverted'/>\n</filters>\n")),
              "s.xml:4: unknown match 'inverted' in <name> filter (the only value is 'inverse')");
    EXPECT_EQ(errorOf(oneService("<filters>\n<name patern='a'/>\n</filters>\n")),
              "s.xml:4: unexpected attribute 'patern' on <name> filter");
    EXPECT_EQ(errorOf(oneService("<filters>\n<name pattern='a'>x</name>\n</filters>\n")),
              "s.xml:4: unexpected text in <name>");
}

TEST(ServicesConfigErrors, UnknownOperator) {
    EXPECT_EQ(errorOf(oneService("<filters operator='xor'/>\n")),
              "s.xml:3: unknown filter operator 'xor' (expected 'and' or 'or')");
    EXPECT_EQ(errorOf(oneService("<filters op='or'/>\n")), "s.xml:3: unexpected attribute 'op' on <filters>");
}

TEST(ServicesConfigErrors, BadPatternNamesFileLineAndPattern) {
    const std::string message = errorOf(oneService("<filters>\n\n<name pattern='police(\\d+'/>\n</filters>\n"));
    const std::string prefix = "s.xml:5: invalid pattern 'police(\\d+' in <name> filter: ";
    EXPECT_EQ(message.substr(0, prefix.size()), prefix) << message;
    EXPECT_GT(message.size(), prefix.size()) << "the regex library's reason follows";
    EXPECT_NE(errorOf(oneService("<filters><type pattern='[a-'/></filters>")).find("invalid pattern '[a-'"),
              std::string::npos);
}

TEST(ServicesConfigErrors, XmlErrorsBecomeServicesConfigErrors) {
    EXPECT_EQ(errorOf("<services>\n<service type='S'>\n</services>"),
              "s.xml:3: mismatched end tag </services>, expected </service> (opened on line 2)");
    EXPECT_EQ(errorOf("<services>\n<service type='S' type='T'/>\n</services>"),
              "s.xml:2: malformed attribute in <service>: an unterminated quote, a missing '=' or quoted value, or a "
              "duplicate attribute");
}

// Malformed XML, one case per kind of mistake: each is one line naming the file and the line.
TEST(ServicesConfigErrors, MalformedXmlNamesTheLine) {
    const std::string unterminatedAttribute =
        ": an unterminated quote, a missing '=' or quoted value, or a duplicate attribute";
    const std::pair<std::string, std::string> cases[] = {
        // end tags
        {"<services>\n<service type='A'></service>\n<service type='B'>\n<listener></listener>\n</services>",
         "s.xml:5: mismatched end tag </services>, expected </service> (opened on line 3)"},
        {"<services>\n<service type='S'><filters>\n  <name pattern='x'>\n  </type >\n</filters></service></services>",
         "s.xml:4: mismatched end tag </type>, expected </name> (opened on line 3)"},
        {"<services>\n<service type='S'>\n</servic\n>\n</services>",
         "s.xml:3: mismatched end tag </servic>, expected </service> (opened on line 2)"},
        {"<services>\n<service type='S'>\n<filters>\n\n",
         "s.xml:3: element never closed (or '<' without an element name)"},
        {"<services>\n  <service type='S'/>\n", "s.xml:1: element never closed (or '<' without an element name)"},
        {"<services>\n<service type='S'>", "s.xml:2: element never closed (or '<' without an element name)"},
        {"<services>\n<>\n</services>", "s.xml:2: element never closed (or '<' without an element name)"},
        {"<services>\n</services", "s.xml:2: unterminated tag <services>"},
        // start tags and attributes
        {"<services>\n<service\n  type='S'\n", "s.xml:2: unterminated tag <service>"},
        {"<services \"x\"/>", "s.xml:1: unexpected character in a tag (expected an attribute, '>' or '/>')"},
        {"<services>\n  <service type=\"S\n  </service>\n</services>\n",
         "s.xml:2: malformed attribute in <service>" + unterminatedAttribute},
        {"<services>\n<service type=S/>\n</services>",
         "s.xml:2: malformed attribute in <service>" + unterminatedAttribute},
        {"<services>\n<service type='S'\n   type='T'/>\n</services>",
         "s.xml:3: malformed attribute in <service>" + unterminatedAttribute},
        {"<services>\n<service\n type/>\n</services>",
         "s.xml:3: malformed attribute in <service>" + unterminatedAttribute},
        // comments, CDATA, declarations
        {"<services>\n<!-- x\n</services>\n", "s.xml:2: unterminated comment"},
        {"<services>\n<![CDATA[ x </services>", "s.xml:2: unterminated CDATA section"},
        {"<?xml version='1.0'\n<services/>",
         "s.xml:1: unterminated or misplaced '<?' (the XML declaration belongs at the start of the file)"},
        {"<services>\n<?xml version='1.0'?></services>",
         "s.xml:2: unterminated or misplaced '<?' (the XML declaration belongs at the start of the file)"},
        {"<!DOCTYPE services>\n<services/>", "s.xml:1: unsupported declaration <!DOCTYPE ...>"},
        {"<services>\n<service type='S'>\n<listener><!ELEMENT a ANY></listener></service></services>",
         "s.xml:3: unsupported declaration <!ELEMENT ...>"},
        {"<services>\n<!DOCTYPE x", "s.xml:2: unterminated '<!' declaration"},
        // around the root
        {"", "s.xml:1: no root element"},
        {"<?xml version='1.0'?>\n<!-- only a comment -->\n", "s.xml:3: no root element"},
        {"\nhello <services/>", "s.xml:2: expected the root element, found text"},
        {"<services/>\n<services/>", "s.xml:2: unexpected content after the root element <services>"},
        {"<services/>\n<![CDATA[x]]>", "s.xml:2: unexpected content after the root element <services>"},
        {"<services/>\n\ntext",
         "s.xml:3: text runs to the end of the file (an element never closed, or text after the root)"},
        {std::string("<services/>\n\n") + '\0' + "<x/>", "s.xml:3: NUL character in the file"},
    };
    for (const auto& [text, message] : cases) EXPECT_EQ(errorOf(text), message) << text;
}

TEST(ServicesConfigErrors, NestingIsLimited) {
    const auto nested = [](int depth) {
        std::string text = "<services>\n<service type='S'>\n<listener>\n";
        for (int i = 0; i < depth; ++i) text += "<d>";
        for (int i = 0; i < depth; ++i) text += "</d>";
        return text + "\n</listener>\n</service>\n</services>\n";
    };
    EXPECT_EQ(onlyService(parse(nested(90))).type, "S");
    EXPECT_EQ(errorOf(nested(1000)), "s.xml:4: elements nested too deeply");
}

// A file in the temporary directory, removed again when the test ends.
class TempFile {
public:
    TempFile(const std::string& stem, std::string_view contents)
        : path_(std::filesystem::temp_directory_path() /
                ("sbsim_services_" + stem + "_" + std::to_string(::getpid()) + ".xml")) {
        std::ofstream(path_) << contents;
    }
    ~TempFile() {
        std::error_code ec;
        std::filesystem::remove(path_, ec);
    }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

TEST(ServicesConfigFile, LoadsAFile) {
    const TempFile file("load", kArteryExample);
    const ServicesConfig config = ServicesConfig::load(file.path());
    ASSERT_EQ(config.services().size(), 3u);
    EXPECT_EQ(config.services()[1].source, file.path().string());
}

// The message ServicesConfig::load gives for `path`, or "no error".
std::string loadErrorOf(const std::filesystem::path& path) {
    try {
        ServicesConfig::load(path);
    } catch (const ServicesConfigError& e) {
        return e.what();
    }
    return "no error";
}

TEST(ServicesConfigFile, ErrorsNameTheFile) {
    const TempFile file("broken", "<services>\n<service/>\n</services>\n");
    EXPECT_EQ(loadErrorOf(file.path()), file.path().string() + ":2: <service> has no 'type' attribute");
}

TEST(ServicesConfigFile, UnreadableFile) {
    const std::filesystem::path missing = std::filesystem::temp_directory_path() / "sbsim_no_such_services.xml";
    EXPECT_EQ(loadErrorOf(missing), missing.string() + ": cannot read");
}

TEST(ServicesConfigFile, ADirectoryIsUnreadable) {
    const std::filesystem::path directory = std::filesystem::temp_directory_path();
    EXPECT_EQ(loadErrorOf(directory), directory.string() + ": cannot read: not a regular file");
}

TEST(ServicesConfigFile, AFifoIsRefusedWithoutOpeningIt) {
    // Opening a FIFO blocks until a writer comes: this test would hang if it were opened.
    const std::filesystem::path fifo = std::filesystem::temp_directory_path() / "sbsim_services_fifo.xml";
    std::filesystem::remove(fifo);
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(loadErrorOf(fifo), fifo.string() + ": cannot read: not a regular file");
    std::filesystem::remove(fifo);
}

TEST(ServicesConfigFile, MalformedXmlInAFileNamesTheFileAndLine) {
    const TempFile file("malformed", "<services>\n  <service type=\"S\">\n  </servic>\n</services>\n");
    EXPECT_EQ(loadErrorOf(file.path()),
              file.path().string() + ":3: mismatched end tag </servic>, expected </service> (opened on line 2)");
}

TEST(ServicesConfigFile, MalformedNumberInALoadedFileNamesTheFile) {
    const TempFile file("number", "<services>\n  <service type=\"PluginService\" range=\"far\"/>\n</services>\n");
    const ServicesConfig config = ServicesConfig::load(file.path());
    try {
        config.services().at(0).number("range", 300);
        FAIL() << "no error";
    } catch (const ServicesConfigError& e) {
        EXPECT_EQ(std::string(e.what()), file.path().string() +
                                             ":2: parameter 'range' of service 'PluginService' must be a number, "
                                             "got 'far'");
    }
}

TEST(ServicesConfigFilters, NestedQuantifiersMatchInLinearTime) {
    // (a+)+$ against "aaa…ab" takes 2^n steps in a backtracking engine (std::regex never returned
    // for 41 characters); RE2 answers at once, whatever the length.
    const ServiceSpec spec = onlyService(parse(oneService("<filters><name pattern='(a+)+$'/></filters>")));
    EXPECT_FALSE(spec.matches(std::string(41, 'a') + "b", "car"));
    EXPECT_FALSE(spec.matches(std::string(1'000'000, 'a') + "b", "car"));
    EXPECT_TRUE(spec.matches(std::string(1'000'000, 'a'), "car"));
}

TEST(ServicesConfigErrors, OverlongPatternIsRefused) {
    const std::string pattern(ServiceFilter::kMaxPatternLength + 1, 'a');
    EXPECT_EQ(errorOf(oneService("<filters>\n<name pattern='" + pattern + "'/>\n</filters>\n")),
              "s.xml:4: the pattern of <name> filter is 1001 characters long (at most 1000)");
    const std::string nested = std::string(450, '(') + "a" + std::string(450, ')');
    EXPECT_NO_THROW(parse(oneService("<filters><name pattern='" + nested + "'/></filters>")));
}

TEST(ServicesConfigEquipment, EquippedVehiclesOnlyUnlessAsked) {
    using Equipment = ServiceSpec::Equipment;
    const ServiceSpec plain = onlyService(parse(oneService("")));
    EXPECT_EQ(plain.equipment, Equipment::Equipped);
    EXPECT_TRUE(plain.admits(true));
    EXPECT_FALSE(plain.admits(false));
    EXPECT_EQ(onlyService(parse(oneService("<filters><equipped/></filters>"))).equipment, Equipment::Equipped);
    const ServiceSpec others = onlyService(parse(oneService("<filters><equipped match='inverse'/></filters>")));
    EXPECT_FALSE(others.admits(true));
    EXPECT_TRUE(others.admits(false));
    const ServiceSpec all = onlyService(parse(oneService("<filters><equipped match='any'/></filters>")));
    EXPECT_TRUE(all.admits(true));
    EXPECT_TRUE(all.admits(false));
    // It applies on top of the name filters, whatever their operator.
    const ServiceSpec named =
        onlyService(parse(oneService("<filters operator='or'><name pattern='p.*'/><equipped match='any'/></filters>")));
    EXPECT_EQ(named.filters.size(), 1U);
    EXPECT_TRUE(named.matches("p1", "car"));
    EXPECT_FALSE(named.matches("q1", "car"));
}

TEST(ServicesConfigErrors, BadEquippedFilter) {
    EXPECT_EQ(errorOf(oneService("<filters>\n<equipped match='some'/>\n</filters>\n")),
              "s.xml:4: unknown match 'some' in <equipped> filter (expected 'inverse' or 'any')");
    EXPECT_EQ(errorOf(oneService("<filters>\n<equipped rate='1'/>\n</filters>\n")),
              "s.xml:4: unexpected attribute 'rate' on <equipped>");
}

// Issue 29: bundled services took misspelt attributes, NaN, infinity, fractions and absurd sizes
// silently (a cause of 1e300 became -2147483648). Each now has a kind and a range, checked at load.
TEST(ServiceAttributes, UnknownAttributesOfABundledTypeAreRefused) {
    EXPECT_EQ(errorOf("<services>\n<service type=\"Beacon\" intervall=\"0.5\"/>\n</services>\n"),
              "s.xml:2: unknown attribute 'intervall' of service 'Beacon' (it takes: bytes, interval, name)");
    // Artery's label is every type's; a plugin's type is not checked.
    EXPECT_EQ(errorOf("<services>\n<service type=\"artery.application.CaService\" name=\"CA\"/>\n</services>\n"),
              "no error");
    EXPECT_EQ(errorOf("<services>\n<service type=\"Mine\" anything=\"x\"/>\n</services>\n"), "no error");
}

TEST(ServiceAttributes, ValuesOfTheWrongKindOrOutOfRangeAreRefused) {
    const auto beacon = [](const std::string& bytes) {
        return errorOf("<services>\n<service type=\"Beacon\" bytes=\"" + bytes + "\"/>\n</services>\n");
    };
    EXPECT_EQ(beacon("190"), "no error");
    for (const std::string bad : {"1e18", "100.5", "0", "nan", "inf", "-1"}) {
        EXPECT_NE(beacon(bad).find("parameter 'bytes' of service 'Beacon' must be"), std::string::npos) << bad;
    }
    EXPECT_EQ(beacon("2305"),
              "s.xml:2: parameter 'bytes' of service 'Beacon' must be a whole number from 1 to 2304, got '2305'");
    EXPECT_EQ(errorOf("<services>\n<rsu id=\"r\" x=\"0\" y=\"0\">\n<service type=\"RsuDenService\" "
                      "cause=\"1e300\"/>\n</rsu>\n</services>\n"),
              "s.xml:3: parameter 'cause' of service 'RsuDenService' must be a whole number from 0 to 255, got "
              "'1e300'");
    EXPECT_EQ(errorOf("<services>\n<service type=\"CaService\" fixedRate=\"yes\"/>\n</services>\n"),
              "s.xml:2: parameter 'fixedRate' of service 'CaService' must be true or false, got 'yes'");
}

TEST(ServiceAttributes, ContradictingAttributesAreRefused) {
    EXPECT_EQ(errorOf("<services>\n<service type=\"CaService\" minInterval=\"2\" maxInterval=\"1\"/>\n</services>\n"),
              "s.xml:2: service 'CaService': minInterval (2 s) is above maxInterval (1 s)");
    // Against the other's default (1 s).
    EXPECT_EQ(errorOf("<services>\n<service type=\"CaService\" minInterval=\"5\"/>\n</services>\n"),
              "s.xml:2: service 'CaService': minInterval (5 s) is above maxInterval (1 s)");
    EXPECT_EQ(
        errorOf("<services>\n<service type=\"CaService\" minInterval=\"0.5\" maxInterval=\"0.5\"/>\n</services>\n"),
        "no error");
}

}  // namespace
}  // namespace sbsim::services

namespace sbsim::services {
namespace {

// Services say what they provide: the run asks the registry, not the type's name.
TEST(ServiceRegistry, TypesSayWhatTheyProvide) {
    const ServiceRegistry& registry = ServiceRegistry::instance();
    const ServiceTraits den = registry.traits("DenService");
    EXPECT_TRUE(den.sendsDenms);
    EXPECT_TRUE(den.runsUseCases);
    const ServiceTraits unit = registry.traits("RsuDenService");
    EXPECT_TRUE(unit.sendsDenms);
    EXPECT_FALSE(unit.runsUseCases);  // not inherited from DenService: the unit says its own
    const ServiceTraits ca = registry.traits("CaService");
    EXPECT_FALSE(ca.sendsDenms);
    EXPECT_FALSE(ca.runsUseCases);
    EXPECT_FALSE(registry.traits("NoSuchService").sendsDenms);
}

// A resolver's types (python:...) answer per entry: what the entry's service provides and its files.
TEST(ServiceRegistry, AResolverAnswersForItsEntries) {
    ServiceRegistry registry;
    registry.addResolver(
        "test:",
        {.check = [](const ServiceSpec&) {},
         .create = [](const ServiceSpec&) { return std::unique_ptr<Service>(); },
         .traits = [](const ServiceSpec& spec) { return ServiceTraits{.sendsDenms = spec.type == "test:sender"}; },
         .files =
             [](const ServiceSpec& spec) { return std::vector<std::filesystem::path>{spec.type.substr(5) + ".py"}; }});
    registry.add(
        "Plain", [] { return std::unique_ptr<Service>(); }, ServiceTraits{.sendsDenms = true});
    ServiceSpec spec;
    spec.type = "test:sender";
    EXPECT_TRUE(registry.traits(spec).sendsDenms);
    EXPECT_EQ(registry.files(spec), std::vector<std::filesystem::path>{"sender.py"});
    EXPECT_FALSE(registry.traits(spec.type).sendsDenms);  // by name alone: not known
    spec.type = "test:quiet";
    EXPECT_FALSE(registry.traits(spec).sendsDenms);
    spec.type = "Plain";  // a registered type: its own traits, no files
    EXPECT_TRUE(registry.traits(spec).sendsDenms);
    EXPECT_TRUE(registry.files(spec).empty());
}

}  // namespace
}  // namespace sbsim::services
