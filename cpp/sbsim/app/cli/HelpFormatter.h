#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace sbsim::app {

/// CLI11's help, laid out for sbsim: an option's default at the end of its text rather than in
/// the option column, the `-- SUMO options` every command accepts in the usage line, one blank
/// line between option groups.
class HelpFormatter : public CLI::Formatter {
public:
    HelpFormatter();

    std::string make_group(std::string group, bool is_positional, std::vector<const CLI::Option*> opts) const override;
    std::string make_usage(const CLI::App* app, std::string name) const override;
    std::string make_option_opts(const CLI::Option* option) const override;
    std::string make_option_desc(const CLI::Option* option) const override;
};

}  // namespace sbsim::app
