#include "sbsim/services/XmlDocument.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>

namespace sbsim::services {

const std::string* XmlElement::attribute(std::string_view attributeName) const {
    for (const auto& [key, value] : attributes) {
        if (key == attributeName) return &value;
    }
    return nullptr;
}

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// ASCII per the XML name production; every byte of a multi-byte UTF-8 sequence is accepted, which
// admits the non-ASCII name characters without decoding them (a few invalid ones slip through).
bool isNameStart(char c) {
    const auto u = static_cast<unsigned char>(c);
    return (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || u == '_' || u == ':' || u >= 0x80;
}

bool isNameChar(char c) { return isNameStart(c) || (c >= '0' && c <= '9') || c == '-' || c == '.'; }

// The XML Char production: what a document (and so a character reference) may contain.
bool isXmlChar(unsigned long cp) {
    return cp == 0x9 || cp == 0xA || cp == 0xD || (cp >= 0x20 && cp <= 0xD7FF) || (cp >= 0xE000 && cp <= 0xFFFD) ||
           (cp >= 0x10000 && cp <= 0x10FFFF);
}

void appendUtf8(std::string& out, unsigned long cp) {
    if (cp < 0x80) {
        out.push_back(static_cast<char>(cp));
    } else if (cp < 0x800) {
        out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else if (cp < 0x10000) {
        out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else {
        out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    }
}

void trim(std::string& s) {
    const auto first = std::find_if_not(s.begin(), s.end(), isSpace);
    const auto last = std::find_if_not(s.rbegin(), s.rend(), isSpace).base();
    s = first < last ? std::string(first, last) : std::string();
}

// A single pass over the whole text; open elements are kept on an explicit stack.
class Parser {
public:
    Parser(std::string_view text, const std::string& source) : text_(text), source_(source) {
        lineStarts_.push_back(0);
        for (std::size_t i = 0; i < text_.size(); ++i) {
            if (text_[i] == '\n') lineStarts_.push_back(i + 1);
        }
    }

    XmlElement parse() {
        if (startsWith("\xEF\xBB\xBF")) pos_ = 3;  // UTF-8 byte order mark
        if (startsWith("<?xml") && pos_ + 5 < text_.size() && (isSpace(text_[pos_ + 5]) || text_[pos_ + 5] == '?')) {
            const std::size_t end = text_.find("?>", pos_);
            if (end == std::string_view::npos) fail(pos_, "unterminated XML declaration");
            pos_ = end + 2;
        }
        skipMisc();
        if (atEnd()) fail(pos_, "no root element");
        if (text_[pos_] != '<') fail(pos_, "expected the root element, found text");
        XmlElement root = parseElement();
        skipMisc();
        if (!atEnd()) fail(pos_, "unexpected content after the root element <" + root.name + ">");
        return root;
    }

private:
    [[noreturn]] void fail(std::size_t pos, const std::string& message) const {
        throw XmlError(source_, lineAt(pos), message);
    }

    int lineAt(std::size_t pos) const {
        return static_cast<int>(std::upper_bound(lineStarts_.begin(), lineStarts_.end(), pos) - lineStarts_.begin());
    }

    bool atEnd() const { return pos_ >= text_.size(); }
    bool startsWith(std::string_view s) const { return text_.substr(pos_).starts_with(s); }

    bool skipSpace() {
        const std::size_t start = pos_;
        while (!atEnd() && isSpace(text_[pos_])) ++pos_;
        return pos_ > start;
    }

    std::string readName() {
        const std::size_t start = pos_;
        while (!atEnd() && isNameChar(text_[pos_])) ++pos_;
        return std::string(text_.substr(start, pos_ - start));
    }

    // Whitespace, comments and processing instructions, as allowed around the root element.
    void skipMisc() {
        while (true) {
            skipSpace();
            if (startsWith("<!--")) {
                skipComment();
            } else if (startsWith("<?")) {
                skipProcessingInstruction();
            } else if (startsWith("<!DOCTYPE")) {
                fail(pos_, "DOCTYPE declarations are not supported");
            } else {
                return;
            }
        }
    }

    void skipComment() {
        const std::size_t start = pos_;
        const std::size_t dashes = text_.find("--", pos_ + 4);
        if (dashes == std::string_view::npos) fail(start, "unterminated comment");
        if (dashes + 2 >= text_.size() || text_[dashes + 2] != '>') {
            fail(dashes, "'--' is not allowed inside a comment");
        }
        pos_ = dashes + 3;
    }

    void skipProcessingInstruction() {
        const std::size_t start = pos_;
        pos_ += 2;
        std::string target = readName();
        if (target.empty()) fail(start, "expected a processing instruction's name after '<?'");
        std::transform(target.begin(), target.end(), target.begin(),
                       [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
        if (target == "xml") fail(start, "the XML declaration is only allowed at the very start of the document");
        const std::size_t end = text_.find("?>", pos_);
        if (end == std::string_view::npos) fail(start, "unterminated processing instruction");
        pos_ = end + 2;
    }

    std::string readCData() {
        const std::size_t start = pos_;
        const std::size_t contentStart = pos_ + 9;  // after "<![CDATA["
        const std::size_t end = text_.find("]]>", contentStart);
        if (end == std::string_view::npos) fail(start, "unterminated CDATA section");
        pos_ = end + 3;
        return std::string(text_.substr(contentStart, end - contentStart));
    }

    XmlElement parseElement() {
        std::vector<XmlElement> open;
        {
            auto [element, selfClosing] = readStartTag();
            if (selfClosing) return std::move(element);
            open.push_back(std::move(element));
        }
        while (true) {
            if (atEnd()) {
                throw XmlError(source_, open.back().line, "element <" + open.back().name + "> is never closed");
            }
            if (text_[pos_] != '<') {
                const std::size_t end = std::min(text_.find('<', pos_), text_.size());
                open.back().text += decode(text_.substr(pos_, end - pos_), pos_, false);
                pos_ = end;
            } else if (startsWith("</")) {
                XmlElement closed = readEndTag(std::move(open.back()));
                open.pop_back();
                if (open.empty()) return closed;
                open.back().children.push_back(std::move(closed));
            } else if (startsWith("<!--")) {
                skipComment();
            } else if (startsWith("<![CDATA[")) {
                open.back().text += readCData();
            } else if (startsWith("<?")) {
                skipProcessingInstruction();
            } else if (startsWith("<!")) {
                fail(pos_, "unsupported markup declaration inside <" + open.back().name + ">");
            } else {
                if (open.size() >= static_cast<std::size_t>(kMaxXmlDepth)) {
                    fail(pos_, "elements nested deeper than " + std::to_string(kMaxXmlDepth) + " levels");
                }
                auto [element, selfClosing] = readStartTag();
                if (selfClosing) {
                    open.back().children.push_back(std::move(element));
                } else {
                    open.push_back(std::move(element));
                }
            }
        }
    }

    // At '<' of a start tag; returns the element (attributes filled in) and whether it was "<x/>".
    std::pair<XmlElement, bool> readStartTag() {
        const std::size_t start = pos_++;
        if (atEnd() || !isNameStart(text_[pos_])) fail(start, "expected an element name after '<'");
        XmlElement element;
        element.line = lineAt(start);
        element.name = readName();
        while (true) {
            const bool hadSpace = skipSpace();
            if (atEnd()) fail(start, "unterminated start tag <" + element.name + ">");
            const char c = text_[pos_];
            if (c == '>') {
                ++pos_;
                return {std::move(element), false};
            }
            if (c == '/') {
                if (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '>') fail(pos_, "expected '>' after '/'");
                pos_ += 2;
                return {std::move(element), true};
            }
            if (!isNameStart(c)) {
                fail(pos_, std::string("unexpected character '") + c + "' in start tag <" + element.name + ">");
            }
            if (!hadSpace) fail(pos_, "missing whitespace before an attribute in <" + element.name + ">");
            readAttribute(element);
        }
    }

    void readAttribute(XmlElement& element) {
        const std::size_t namePos = pos_;
        std::string name = readName();
        skipSpace();
        if (atEnd() || text_[pos_] != '=') fail(pos_, "attribute '" + name + "' has no value (expected '=')");
        ++pos_;
        skipSpace();
        if (atEnd() || (text_[pos_] != '"' && text_[pos_] != '\'')) {
            fail(pos_, "the value of attribute '" + name + "' must be quoted");
        }
        const char quote = text_[pos_];
        const std::size_t valueStart = pos_ + 1;
        const std::size_t valueEnd = text_.find(quote, valueStart);
        if (valueEnd == std::string_view::npos) fail(pos_, "unterminated value of attribute '" + name + "'");
        const std::string_view raw = text_.substr(valueStart, valueEnd - valueStart);
        // A '<' inside almost always means the closing quote is missing, so point at the opening one.
        if (raw.find('<') != std::string_view::npos) {
            fail(pos_, "'<' in the value of attribute '" + name + "' (unterminated quote?)");
        }
        if (element.attribute(name)) fail(namePos, "duplicate attribute '" + name + "' in <" + element.name + ">");
        std::string value = decode(raw, valueStart, true);
        element.attributes.emplace_back(std::move(name), std::move(value));
        pos_ = valueEnd + 1;
    }

    // At "</"; checks the name against the innermost open element and returns that element.
    XmlElement readEndTag(XmlElement element) {
        const std::size_t start = pos_;
        pos_ += 2;
        const std::string name = readName();
        skipSpace();
        if (atEnd() || text_[pos_] != '>') fail(pos_, "expected '>' to close end tag </" + name + ">");
        ++pos_;
        if (name != element.name) {
            fail(start, "mismatched end tag </" + name + ">, expected </" + element.name + "> (opened on line " +
                            std::to_string(element.line) + ")");
        }
        trim(element.text);
        return element;
    }

    // Character data with references resolved and line ends normalized; attribute values also get
    // literal whitespace turned into spaces, as XML's attribute-value normalization requires.
    std::string decode(std::string_view raw, std::size_t rawPos, bool attribute) const {
        std::string out;
        out.reserve(raw.size());
        for (std::size_t i = 0; i < raw.size(); ++i) {
            const char c = raw[i];
            if (c == '&') {
                i = decodeReference(raw, i, rawPos, out);
            } else if (c == '\r') {
                out.push_back(attribute ? ' ' : '\n');
                if (i + 1 < raw.size() && raw[i + 1] == '\n') ++i;
            } else if (attribute && (c == '\n' || c == '\t')) {
                out.push_back(' ');
            } else if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') {
                fail(rawPos + i, "control character " + std::to_string(static_cast<int>(c)) + " is not allowed");
            } else {
                out.push_back(c);
            }
        }
        return out;
    }

    // At the '&' of raw[amp]; appends the referenced character and returns the index of the ';'.
    std::size_t decodeReference(std::string_view raw, std::size_t amp, std::size_t rawPos, std::string& out) const {
        const std::size_t semi = raw.find(';', amp);
        const std::string_view ref =
            semi == std::string_view::npos ? std::string_view() : raw.substr(amp + 1, semi - amp - 1);
        const bool numeric = ref.starts_with('#');
        const std::string_view body = numeric ? ref.substr(1) : ref;
        if (body.empty() || !std::all_of(body.begin(), body.end(), isNameChar)) {
            fail(rawPos + amp, "'&' must start an entity or character reference (write &amp; for a literal '&')");
        }
        if (!numeric) {
            static constexpr std::pair<std::string_view, char> kEntities[] = {
                {"lt", '<'}, {"gt", '>'}, {"amp", '&'}, {"quot", '"'}, {"apos", '\''}};
            for (const auto& [entity, c] : kEntities) {
                if (ref == entity) {
                    out.push_back(c);
                    return semi;
                }
            }
            fail(rawPos + amp, "unknown entity '&" + std::string(ref) + ";'");
        }
        const bool hex = body.starts_with('x');
        const std::string_view digits = hex ? body.substr(1) : body;
        unsigned long cp = 0;
        bool valid = !digits.empty();
        for (const char d : digits) {
            int v = -1;
            if (d >= '0' && d <= '9') v = d - '0';
            if (hex && d >= 'a' && d <= 'f') v = d - 'a' + 10;
            if (hex && d >= 'A' && d <= 'F') v = d - 'A' + 10;
            if (v < 0) valid = false;
            if (!valid) break;
            cp = cp * (hex ? 16 : 10) + static_cast<unsigned long>(v);
            if (cp > 0x10FFFF) break;  // keeps the value bounded; rejected below
        }
        if (!valid) fail(rawPos + amp, "malformed character reference '&" + std::string(ref) + ";'");
        if (!isXmlChar(cp)) {
            fail(rawPos + amp, "character reference '&" + std::string(ref) + ";' is not an XML character");
        }
        appendUtf8(out, cp);
        return semi;
    }

    std::string_view text_;
    const std::string& source_;
    std::vector<std::size_t> lineStarts_;  // offset of each line's first character
    std::size_t pos_ = 0;
};

}  // namespace

XmlElement parseXml(std::string_view text, const std::string& source) { return Parser(text, source).parse(); }

XmlElement readXmlFile(const std::filesystem::path& path) {
    const std::string source = path.string();
    std::error_code ec;
    // An ifstream opens a directory without complaint and then reads nothing.
    if (std::filesystem::is_directory(path, ec)) throw XmlError(source + ": cannot read");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw XmlError(source + ": cannot read");
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw XmlError(source + ": cannot read");
    return parseXml(text, source);
}

}  // namespace sbsim::services
