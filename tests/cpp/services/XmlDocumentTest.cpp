#include "sbsim/services/XmlDocument.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace sbsim::services {
namespace {

// The error message parseXml gives for `text` (source "t.xml"), or "no error".
std::string errorOf(std::string_view text) {
    try {
        parseXml(text, "t.xml");
    } catch (const XmlError& e) {
        return e.what();
    }
    return "no error";
}

// A file in the temporary directory, removed again when the test ends.
class TempPath {
public:
    explicit TempPath(const std::string& stem)
        : path_(std::filesystem::temp_directory_path() /
                ("sbsim_xml_" + stem + "_" + std::to_string(::getpid()) + ".xml")) {}
    ~TempPath() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

TEST(XmlDocument, SelfClosingRoot) {
    const XmlElement root = parseXml("<a/>", "t.xml");
    EXPECT_EQ(root.name, "a");
    EXPECT_EQ(root.line, 1);
    EXPECT_TRUE(root.attributes.empty());
    EXPECT_TRUE(root.children.empty());
    EXPECT_EQ(root.text, "");
}

TEST(XmlDocument, NestedElementsAttributesAndLines) {
    const XmlElement root = parseXml(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<!-- leading comment -->\n"
        "<root version='2'>\n"
        "  <child name=\"one\" kind='x'/>\n"
        "  <child\n"
        "      name = \"two\" >\n"
        "    <grandchild/>\n"
        "  </child>\n"
        "</root >\n"
        "<!-- trailing comment -->\n",
        "t.xml");
    EXPECT_EQ(root.name, "root");
    EXPECT_EQ(root.line, 3);
    ASSERT_NE(root.attribute("version"), nullptr);
    EXPECT_EQ(*root.attribute("version"), "2");
    EXPECT_EQ(root.attribute("missing"), nullptr);
    ASSERT_EQ(root.children.size(), 2u);

    const XmlElement& first = root.children[0];
    EXPECT_EQ(first.line, 4);
    ASSERT_EQ(first.attributes.size(), 2u);  // document order
    EXPECT_EQ(first.attributes[0], (std::pair<std::string, std::string>{"name", "one"}));
    EXPECT_EQ(first.attributes[1], (std::pair<std::string, std::string>{"kind", "x"}));

    const XmlElement& second = root.children[1];
    EXPECT_EQ(second.line, 5);
    EXPECT_EQ(*second.attribute("name"), "two");
    ASSERT_EQ(second.children.size(), 1u);
    EXPECT_EQ(second.children[0].name, "grandchild");
    EXPECT_EQ(second.children[0].line, 7);
    EXPECT_EQ(second.text, "");
}

TEST(XmlDocument, QuotesOfTheOtherKindInsideValues) {
    const XmlElement root = parseXml(R"(<a x='say "hi"' y="it's"/>)", "t.xml");
    EXPECT_EQ(*root.attribute("x"), "say \"hi\"");
    EXPECT_EQ(*root.attribute("y"), "it's");
}

TEST(XmlDocument, TextIsTrimmedAndConcatenatedAroundChildren) {
    const XmlElement root = parseXml("<a>\n  hello <b>inner</b> world \n</a>", "t.xml");
    EXPECT_EQ(root.text, "hello  world");
    EXPECT_EQ(root.children.at(0).text, "inner");
}

TEST(XmlDocument, PredefinedEntities) {
    const XmlElement root = parseXml("<a v=\"&lt;&gt;&amp;&quot;&apos;\">&lt;&gt;&amp;&quot;&apos;</a>", "t.xml");
    EXPECT_EQ(*root.attribute("v"), "<>&\"'");
    EXPECT_EQ(root.text, "<>&\"'");
}

TEST(XmlDocument, CharacterReferencesDecodeToUtf8) {
    const XmlElement root = parseXml("<a>&#65;&#x42;&#x20AC;&#128512; &amp;amp;</a>", "t.xml");
    EXPECT_EQ(root.text, "AB\xE2\x82\xAC\xF0\x9F\x98\x80 &amp;");
}

TEST(XmlDocument, CDataIsKeptVerbatim) {
    const XmlElement root = parseXml("<a>x <![CDATA[<raw> & ]]]]><![CDATA[>]]></a>", "t.xml");
    EXPECT_EQ(root.text, "x <raw> & ]]>");
}

TEST(XmlDocument, AttributeWhitespaceIsNormalizedButReferencesAreKept) {
    const XmlElement root = parseXml("<a v=\"x\ny\tz\r\nw\" r=\"1&#10;2\"/>", "t.xml");
    EXPECT_EQ(*root.attribute("v"), "x y z w");
    EXPECT_EQ(*root.attribute("r"), "1\n2");
}

TEST(XmlDocument, CarriageReturnsInTextBecomeNewlines) {
    EXPECT_EQ(parseXml("<a>1\r\n2\r3</a>", "t.xml").text, "1\n2\n3");
}

TEST(XmlDocument, CommentsProcessingInstructionsAndByteOrderMark) {
    const XmlElement root = parseXml(
        "\xEF\xBB\xBF<?xml version='1.0'?><?style x?>\n"
        "<a><!-- a - b --><?pi inside?><!----><b/></a>",
        "t.xml");
    EXPECT_EQ(root.name, "a");
    EXPECT_EQ(root.line, 2);
    ASSERT_EQ(root.children.size(), 1u);
    EXPECT_EQ(root.children[0].name, "b");
}

TEST(XmlDocument, NamesWithPunctuationAndNonAscii) {
    const XmlElement root = parseXml("<ns:a-b.c_1 x-y.z='1'><\xC3\xA9l\xC3\xA9ment/></ns:a-b.c_1>", "t.xml");
    EXPECT_EQ(root.name, "ns:a-b.c_1");
    EXPECT_EQ(*root.attribute("x-y.z"), "1");
    EXPECT_EQ(root.children.at(0).name, "\xC3\xA9l\xC3\xA9ment");
}

TEST(XmlDocument, NestingIsLimited) {
    const auto nested = [](int depth) {
        std::string text;
        for (int i = 0; i < depth; ++i) text += "<d>";
        for (int i = 0; i < depth; ++i) text += "</d>";
        return text;
    };
    EXPECT_EQ(parseXml(nested(kMaxXmlDepth), "t.xml").children.size(), 1u);
    EXPECT_EQ(errorOf(nested(kMaxXmlDepth + 1)), "t.xml:1: elements nested deeper than 256 levels");
}

// --- errors: every message names the source and the line the problem is on ---

TEST(XmlDocumentErrors, ElementNeverClosedNamesItsOpeningLine) {
    EXPECT_EQ(errorOf("<a>\n  <b>\n\n"), "t.xml:2: element <b> is never closed");
    EXPECT_EQ(errorOf("<a>\n  <b/>\n"), "t.xml:1: element <a> is never closed");
}

TEST(XmlDocumentErrors, MismatchedEndTag) {
    EXPECT_EQ(errorOf("<a>\n<b>\n</a>\n</b>"), "t.xml:3: mismatched end tag </a>, expected </b> (opened on line 2)");
    EXPECT_EQ(errorOf("<a>\n</a >x"), "t.xml:2: unexpected content after the root element <a>");
}

TEST(XmlDocumentErrors, UnterminatedEndTag) {
    EXPECT_EQ(errorOf("<a>\n</a"), "t.xml:2: expected '>' to close end tag </a>");
}

TEST(XmlDocumentErrors, DuplicateAttribute) {
    EXPECT_EQ(errorOf("<a x=\"1\"\n   x='2'/>"), "t.xml:2: duplicate attribute 'x' in <a>");
}

TEST(XmlDocumentErrors, ContentAfterTheRoot) {
    EXPECT_EQ(errorOf("<a/>\n\ntext"), "t.xml:3: unexpected content after the root element <a>");
    EXPECT_EQ(errorOf("<a/>\n<b/>"), "t.xml:2: unexpected content after the root element <a>");
}

TEST(XmlDocumentErrors, NoRoot) {
    EXPECT_EQ(errorOf(""), "t.xml:1: no root element");
    EXPECT_EQ(errorOf("<?xml version='1.0'?>\n<!-- only a comment -->\n"), "t.xml:3: no root element");
    EXPECT_EQ(errorOf("\nhello <a/>"), "t.xml:2: expected the root element, found text");
}

TEST(XmlDocumentErrors, UnterminatedComment) {
    EXPECT_EQ(errorOf("<a>\n<!-- x\n</a>\n"), "t.xml:2: unterminated comment");
    EXPECT_EQ(errorOf("<!-- x\n<a/>"), "t.xml:1: unterminated comment");
}

TEST(XmlDocumentErrors, DoubleDashInComment) {
    EXPECT_EQ(errorOf("<a>\n<!-- x\n -- y --></a>"), "t.xml:3: '--' is not allowed inside a comment");
}

TEST(XmlDocumentErrors, UnterminatedQuote) {
    EXPECT_EQ(errorOf("<a>\n  <b x=\"1/>\n</a>"), "t.xml:2: unterminated value of attribute 'x'");
    // With a later quote in the file the value runs into the next tag: still reported at the opening quote.
    EXPECT_EQ(errorOf("<a>\n  <b x='1/>\n  <c y='2'/>\n</a>"),
              "t.xml:2: '<' in the value of attribute 'x' (unterminated quote?)");
}

TEST(XmlDocumentErrors, MalformedAttributes) {
    EXPECT_EQ(errorOf("<a x=1/>"), "t.xml:1: the value of attribute 'x' must be quoted");
    EXPECT_EQ(errorOf("<a\n x/>"), "t.xml:2: attribute 'x' has no value (expected '=')");
    EXPECT_EQ(errorOf("<a x='1'y='2'/>"), "t.xml:1: missing whitespace before an attribute in <a>");
    EXPECT_EQ(errorOf("<a \"x\"/>"), "t.xml:1: unexpected character '\"' in start tag <a>");
    EXPECT_EQ(errorOf("<a x='1' / >"), "t.xml:1: expected '>' after '/'");
}

TEST(XmlDocumentErrors, UnterminatedStartTag) {
    EXPECT_EQ(errorOf("<r>\n<a\n  x='1'\n"), "t.xml:2: unterminated start tag <a>");
    EXPECT_EQ(errorOf("<r>\n< a/></r>"), "t.xml:2: expected an element name after '<'");
    EXPECT_EQ(errorOf("</r>"), "t.xml:1: expected an element name after '<'");
}

TEST(XmlDocumentErrors, BadReferences) {
    EXPECT_EQ(errorOf("<a>\n&nbsp;</a>"), "t.xml:2: unknown entity '&nbsp;'");
    EXPECT_EQ(errorOf("<a>\nfish & chips; </a>"),
              "t.xml:2: '&' must start an entity or character reference (write &amp; for a literal '&')");
    EXPECT_EQ(errorOf("<a v='x &amp'/>"),
              "t.xml:1: '&' must start an entity or character reference (write &amp; for a literal '&')");
    EXPECT_EQ(errorOf("<a>&#xZZ;</a>"), "t.xml:1: malformed character reference '&#xZZ;'");
    EXPECT_EQ(errorOf("<a>&#X43;</a>"), "t.xml:1: malformed character reference '&#X43;'");
    EXPECT_EQ(errorOf("<a>&#12a;</a>"), "t.xml:1: malformed character reference '&#12a;'");
    EXPECT_EQ(errorOf("<a>&#0;</a>"), "t.xml:1: character reference '&#0;' is not an XML character");
    EXPECT_EQ(errorOf("<a>&#xD800;</a>"), "t.xml:1: character reference '&#xD800;' is not an XML character");
    EXPECT_EQ(errorOf("<a>&#x110000;</a>"), "t.xml:1: character reference '&#x110000;' is not an XML character");
    EXPECT_EQ(errorOf("<a>&#99999999999999999999;</a>"),
              "t.xml:1: character reference '&#99999999999999999999;' is not an XML character");
}

TEST(XmlDocumentErrors, ControlCharacter) {
    EXPECT_EQ(errorOf("<a>\n\x01</a>"), "t.xml:2: control character 1 is not allowed");
}

TEST(XmlDocumentErrors, DeclarationsAndOtherMarkup) {
    EXPECT_EQ(errorOf("\n<?xml version='1.0'?><a/>"),
              "t.xml:2: the XML declaration is only allowed at the very start of the document");
    EXPECT_EQ(errorOf("<?xml version='1.0'\n<a/>"), "t.xml:1: unterminated XML declaration");
    EXPECT_EQ(errorOf("<a>\n<?pi x </a>"), "t.xml:2: unterminated processing instruction");
    EXPECT_EQ(errorOf("<a>\n<? x?></a>"), "t.xml:2: expected a processing instruction's name after '<?'");
    EXPECT_EQ(errorOf("<a><?XML x?></a>"),
              "t.xml:1: the XML declaration is only allowed at the very start of the document");
    EXPECT_EQ(errorOf("<!DOCTYPE a>\n<a/>"), "t.xml:1: DOCTYPE declarations are not supported");
    EXPECT_EQ(errorOf("<a>\n<!ELEMENT a ANY></a>"), "t.xml:2: unsupported markup declaration inside <a>");
    EXPECT_EQ(errorOf("<a>\n<![CDATA[ x </a>"), "t.xml:2: unterminated CDATA section");
}

TEST(XmlDocumentErrors, IsARuntimeErrorAndKnowsItsLine) {
    try {
        parseXml("<a>\n\n<b></a>", "file.xml");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        const auto* xml = dynamic_cast<const XmlError*>(&e);
        ASSERT_NE(xml, nullptr);
        EXPECT_EQ(xml->line(), 3);
        EXPECT_EQ(std::string(e.what()), "file.xml:3: mismatched end tag </a>, expected </b> (opened on line 3)");
    }
}

TEST(XmlFile, ReadsAFile) {
    const TempPath file("read");
    std::ofstream(file.path()) << "<?xml version=\"1.0\"?>\n<a>\n  <b x=\"1\"/>\n</a>\n";
    const XmlElement root = readXmlFile(file.path());
    EXPECT_EQ(root.name, "a");
    EXPECT_EQ(root.children.at(0).line, 3);
}

TEST(XmlFile, ErrorsNameThePath) {
    const TempPath file("broken");
    std::ofstream(file.path()) << "<a>\n<b>\n</a>\n";
    try {
        readXmlFile(file.path());
        FAIL() << "no error";
    } catch (const XmlError& e) {
        EXPECT_EQ(std::string(e.what()),
                  file.path().string() + ":3: mismatched end tag </a>, expected </b> (opened on line 2)");
    }
}

TEST(XmlFile, UnreadableFile) {
    const TempPath missing("missing");
    try {
        readXmlFile(missing.path());
        FAIL() << "no error";
    } catch (const XmlError& e) {
        EXPECT_EQ(std::string(e.what()), missing.path().string() + ": cannot read");
        EXPECT_EQ(e.line(), 0);
    }
    const TempPath directory("directory");
    std::filesystem::create_directory(directory.path());
    EXPECT_THROW(readXmlFile(directory.path()), XmlError);
}

}  // namespace
}  // namespace sbsim::services
