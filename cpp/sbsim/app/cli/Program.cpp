#include "sbsim/app/cli/Program.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <memory>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/cli/CommandLine.h"
#include "sbsim/app/cli/HelpFormatter.h"
#include "sbsim/app/cli/Subcommands.h"
#include "sbsim/app/inputs/OpenScenarioImport.h"
#include "sbsim/app/inputs/ProjData.h"
#include "sbsim/app/run/Interruption.h"
#include "sbsim/kernel/OneLine.h"
#include "sbsim/storyboard/StoryError.h"

namespace sbsim::app {

namespace {

constexpr const char* kDescription =
    "Runs SUMO through libsumo, with an Artery-style storyboard making traffic dynamic.\n"
    "Without --sumocfg, runs the bundled scenario (stories/grid-rain) and its story.\n";

constexpr const char* kFooter =
    "Words after -- go to SUMO as they are, e.g. sbsim --story s.py -- -c x.sumocfg --begin 600;\n"
    "a -c FILE or --configuration-file FILE among them is the SUMO configuration.\n"
    "Exit codes: 0 done, 2 bad input (SUMO's errors included), 3 a story's criterion failed,\n"
    "130 interrupted (SIGINT, SIGTERM), 1 an internal error.";

/// The command line up to its first `--`, and the words after it (SUMO's). Split here rather than
/// by CLI11, which would take the words after `--`, and stray ones before it, as positionals alike.
struct Words {
    std::vector<std::string> sbsim;
    std::vector<std::string> sumo;
};

Words splitAtDashes(const std::vector<std::string>& args) {
    const auto dashes = std::find(args.begin(), args.end(), "--");
    return {{args.begin(), dashes}, {dashes == args.end() ? dashes : dashes + 1, args.end()}};
}

/// Parses and dispatches: a subcommand if one was named, else the simulation run.
/// The option `name` ("--quiet") of `app` or of one of its subcommands, or null.
const CLI::Option* findOption(const CLI::App& app, const std::string& name) {
    if (const CLI::Option* option = app.get_option_no_throw(name)) return option;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
        if (const CLI::Option* option = sub->get_option_no_throw(name)) return option;
    }
    return nullptr;
}

/// What CLI11 lets through or reports as something else: a flag given a value (`--quiet=yes`,
/// a flag takes none) and an empty value after '=' (`--sumocfg=`, which CLI11 reports as a stray
/// later word).
void rejectOddValues(const CLI::App& app, const std::vector<std::string>& words) {
    for (const std::string& word : words) {
        const std::size_t equals = word.find('=');
        if (!word.starts_with("--") || equals == std::string::npos) continue;
        const std::string name = word.substr(0, equals);
        const CLI::Option* option = findOption(app, name);
        if (option == nullptr) continue;  // CLI11 names the unknown option
        if (option->get_expected_max() == 0) {
            throw UsageError(fmt::format("{}: a flag takes no value (given '{}')", name, word));
        }
        if (equals + 1 == word.size()) {
            const std::string type = option->get_type_name();  // FILE, FILE.jsonl, LIB.so
            const bool file = type.starts_with("FILE") || type.starts_with("LIB");
            throw UsageError(fmt::format("{}: the {} is empty", name, file ? "file name" : "value"));
        }
    }
}

int parseAndRun(const std::vector<std::string>& args) {
    CLI::App app(kDescription, "sbsim");
    app.formatter(std::make_shared<HelpFormatter>());
    app.set_help_flag("-h,--help", "print this help and exit");
    app.set_version_flag("--version", fmt::format("sbsim {}", SBSIM_VERSION), "print the version and exit");
    app.footer(kFooter);
    CommandLine options;
    options.arguments = args;
    options.declareOptions(app);

    const std::vector<std::unique_ptr<Subcommand>> subcommands = makeSubcommands();
    for (const std::unique_ptr<Subcommand>& subcommand : subcommands) {
        CLI::App* command = app.add_subcommand(subcommand->name(), subcommand->description());
        command->fallthrough();  // the run's options after the subcommand's name go to sbsim's
        command->footer(fmt::format("sbsim's options (sbsim --help) are accepted after '{}' too.\n{}",
                                    subcommand->name(), kFooter));
        subcommand->declareOptions(*command);
    }
    app.require_subcommand(0, 1);

    Words words = splitAtDashes(args);
    rejectOddValues(app, words.sbsim);
    std::reverse(words.sbsim.begin(), words.sbsim.end());  // CLI11 parses from the back
    try {
        app.parse(words.sbsim);
    } catch (const CLI::CallForHelp&) {
        fmt::print("{}", app.help());  // the named subcommand's help, if there is one
        return 0;
    } catch (const CLI::CallForVersion& e) {
        fmt::print("{}\n", e.what());
        return 0;
    } catch (const CLI::ExtrasError& e) {
        throw UsageError(fmt::format("{} (see sbsim --help)", e.what()));
    } catch (const CLI::ParseError& e) {
        throw UsageError(e.what());
    }
    options.complete(std::move(words.sumo));
    if (options.scenario) {
        importOpenScenario(options);
    } else if (!options.binds.empty()) {
        throw UsageError("--bind: it names a scenario's entity; give --scenario too");
    }

    for (const std::unique_ptr<Subcommand>& subcommand : subcommands) {
        if (app.got_subcommand(subcommand->name())) return subcommand->run(options);
    }
    return defaultSubcommand(subcommands).run(options);  // sbsim [options]: the run
}

}  // namespace

/// Writes a message to stderr; never throws, whatever stderr is (a story may have closed it): the
/// exit code must survive a lost message.
void say(const std::string& text) noexcept {
    (void)std::fputs(text.c_str(), stderr);
    (void)std::fflush(stderr);
}

int runProgram(const std::vector<std::string>& args) {
    Interruption::install();
    pointProjAtSumoData();  // before SUMO is loaded: PROJ reads the variables once
    // Once interrupted, a failure other than bad input is the interruption's doing (a story's
    // KeyboardInterrupt, SUMO closed midway): exit code 130, not the failure's.
    const auto interrupted = [] {
        say("sbsim: interrupted\n");
        return 130;
    };
    try {
        return parseAndRun(args);
    } catch (const Interrupted& e) {
        say(fmt::format("sbsim: interrupted {}\n", kernel::escapeControls(e.what())));
        return 130;
    } catch (const BadInput& e) {
        say(fmt::format("sbsim: {}\n", kernel::escapeControls(e.what())));
        return 2;
    } catch (const storyboard::StoryError& e) {
        if (Interruption::requested()) return interrupted();
        say(fmt::format("{}sbsim: {}\n", e.details(), kernel::escapeControls(e.what())));
        return 2;
    } catch (const std::exception& e) {
        if (Interruption::requested()) return interrupted();
        say(fmt::format("sbsim: error: {}\n", kernel::escapeControls(e.what())));
        return 1;
    }
}

}  // namespace sbsim::app
