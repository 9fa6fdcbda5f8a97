#include "sbsim/app/cli/Program.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/cli/CommandLine.h"
#include "sbsim/app/cli/HelpFormatter.h"
#include "sbsim/app/cli/Subcommands.h"
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

    for (const std::unique_ptr<Subcommand>& subcommand : subcommands) {
        if (app.got_subcommand(subcommand->name())) return subcommand->run(options);
    }
    return defaultSubcommand(subcommands).run(options);  // sbsim [options]: the run
}

}  // namespace

int runProgram(const std::vector<std::string>& args) {
    Interruption::install();
    pointProjAtSumoData();  // before SUMO is loaded: PROJ reads the variables once
    // Once interrupted, a failure other than bad input is the interruption's doing (a story's
    // KeyboardInterrupt, SUMO closed midway): exit code 130, not the failure's.
    const auto interrupted = [] {
        fmt::print(stderr, "sbsim: interrupted\n");
        return 130;
    };
    try {
        return parseAndRun(args);
    } catch (const Interrupted& e) {
        fmt::print(stderr, "sbsim: interrupted {}\n", kernel::escapeControls(e.what()));
        return 130;
    } catch (const BadInput& e) {
        fmt::print(stderr, "sbsim: {}\n", kernel::escapeControls(e.what()));
        return 2;
    } catch (const storyboard::StoryError& e) {
        if (Interruption::requested()) return interrupted();
        fmt::print(stderr, "{}sbsim: {}\n", e.details(), kernel::escapeControls(e.what()));
        return 2;
    } catch (const std::exception& e) {
        if (Interruption::requested()) return interrupted();
        fmt::print(stderr, "sbsim: error: {}\n", kernel::escapeControls(e.what()));
        return 1;
    }
}

}  // namespace sbsim::app
