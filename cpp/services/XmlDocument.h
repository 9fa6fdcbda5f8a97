#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::services {

/// parseXml rejects deeper documents: configuration files are shallow, and the element tree's
/// destructor recurses once per level.
inline constexpr int kMaxXmlDepth = 256;

/// A malformed or unreadable XML file. what() is "<source>:<line>: <message>" (or
/// "<path>: cannot read" when the file cannot be opened), so it can be shown to the user as is.
class SBSIM_API XmlError : public std::runtime_error {
public:
    XmlError(const std::string& source, int line, const std::string& message)
        : std::runtime_error(source + ":" + std::to_string(line) + ": " + message), line_(line) {}
    /// An error not tied to a line (an unreadable file); line() is 0.
    explicit XmlError(const std::string& what) : std::runtime_error(what), line_(0) {}
    int line() const { return line_; }

private:
    int line_;
};

/// One element of a parsed document. Attributes keep their document order; `text` is the
/// element's own character data (CDATA included, children's excluded), entity-decoded and trimmed.
struct SBSIM_API XmlElement {
    std::string name;
    std::vector<std::pair<std::string, std::string>> attributes;
    std::vector<XmlElement> children;
    std::string text;
    int line = 0;  ///< 1-based line of the start tag's '<'.

    /// The attribute's decoded value, or nullptr if the element has none by that name.
    const std::string* attribute(std::string_view attributeName) const;
};

/// Parses a whole document and returns its root element. Strict on purpose (configuration typos
/// should fail loudly): well-formedness errors throw XmlError. Supports the XML declaration and
/// other processing instructions (skipped), comments, CDATA, the five predefined entities and
/// character references; a DOCTYPE is rejected. `source` only names the text in error messages.
XmlElement parseXml(std::string_view text, const std::string& source);

/// Reads and parses a file; the path (as given) is the error messages' source.
XmlElement readXmlFile(const std::filesystem::path& path);

}  // namespace sbsim::services
