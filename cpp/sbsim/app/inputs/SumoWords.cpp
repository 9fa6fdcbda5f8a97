#include "sbsim/app/inputs/SumoWords.h"

#include <fmt/format.h>
#include <wordexp.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>

#include "sbsim/app/cli/BadInput.h"

namespace sbsim::app {

namespace {

const char* wordexpProblem(int code) {
    switch (code) {
        case WRDE_BADCHAR:
            return "an unquoted shell special character (one of |&;<>(){} or a newline): quote it";
        case WRDE_BADVAL:
            return "an unset shell variable";
        case WRDE_CMDSUB:
            return "command substitution ($(...) or `...`), which is not run";
        case WRDE_SYNTAX:
            return "a shell syntax error, such as an unterminated quote";
        case WRDE_NOSPACE:
            return "out of memory";
        default:
            return "cannot split it into words";
    }
}

}  // namespace

std::vector<std::string> splitSumoOption(const std::string& text) {
    wordexp_t words{};
    // wordexp allocates even when it fails with WRDE_NOSPACE; the deleter frees whatever it made.
    const int code = wordexp(text.c_str(), &words, WRDE_NOCMD | WRDE_UNDEF);
    const std::unique_ptr<wordexp_t, void (*)(wordexp_t*)> guard(&words, wordfree);
    if (code != 0) throw UsageError(fmt::format("--sumo-option: '{}': {}", text, wordexpProblem(code)));
    return {words.we_wordv, words.we_wordv + words.we_wordc};
}

std::optional<std::filesystem::path> takeConfigurationFile(std::vector<std::string>& sumoArgs) {
    // CLI11 picks SUMO's option out with SUMO's spellings (`-c F`, `--configuration-file F`,
    // `--configuration-file=F`) and keeps every other word, in order, as an extra.
    CLI::App sumo("", "sumo");
    sumo.set_help_flag();  // SUMO's -h is SUMO's business
    sumo.allow_extras();
    std::optional<std::string> file;
    sumo.add_option("-c,--configuration-file", file)->type_name("FILE");
    std::vector<std::string> reversed(sumoArgs.rbegin(), sumoArgs.rend());  // CLI11 parses from the back
    try {
        sumo.parse(reversed);
    } catch (const CLI::ParseError& e) {
        throw UsageError(fmt::format("SUMO options after --: {}", e.what()));
    }
    if (!file) return std::nullopt;
    sumoArgs = sumo.remaining();
    return std::filesystem::path(*file);
}

}  // namespace sbsim::app
