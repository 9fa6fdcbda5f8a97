#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace sbsim::app {

/// SUMO's option table as the SUMO sbsim links writes it (`sumo --save-template`, run when sbsim is
/// configured and built into the program): every option's long name, its synonyms, its type and
/// its section. sbsim asks it which option a word or a sumocfg element names and which options
/// are files SUMO reads, rather than keeping a list of its own that SUMO's aliases would escape.
/// Reading the table costs about 1 ms once; asking the `sumo` binary per run (`--save-configuration`)
/// would cost about 350 ms.
class SumoOptionTable {
public:
    /// The table of the SUMO sbsim was built with (parsed once, on first use).
    static const SumoOptionTable& instance();

    /// Parses a template as `sumo --save-template` writes it; throws std::runtime_error if it
    /// does not parse.
    explicit SumoOptionTable(const char* templateXml);

    /// The long name of the option `name` spells (a long name, a synonym or a one-letter
    /// abbreviation); empty for a name SUMO does not know.
    std::string canonical(std::string_view name) const;
    /// Whether option `name` (a long name) is a file SUMO reads: a FILE option of the input
    /// section, or any other FILE option that is not written (outputs, logs, saved
    /// configurations) such as lookup tables and replayed traces.
    bool isReadFile(std::string_view name) const;
    /// Whether option `name` (a long name) is a boolean (set by its name alone on a command line).
    bool isBool(std::string_view name) const;
    /// Every option that is a file SUMO reads, long names.
    const std::vector<std::string>& readFiles() const { return readFiles_; }

private:
    struct Option {
        std::string section;
        std::string type;
    };
    std::map<std::string, Option, std::less<>> options_;
    std::map<std::string, std::string, std::less<>> synonyms_;  ///< synonym -> long name
    std::vector<std::string> readFiles_;
};

}  // namespace sbsim::app
