#include "sbsim/app/cli/HelpFormatter.h"

#include <fmt/format.h>

namespace sbsim::app {

HelpFormatter::HelpFormatter() { column_width(33); }  // fits "--middleware-interval SECONDS"

std::string HelpFormatter::make_group(std::string group, bool is_positional,
                                      std::vector<const CLI::Option*> opts) const {
    // CLI11 starts each group with a blank line and also puts one between groups.
    std::string text = CLI::Formatter::make_group(std::move(group), is_positional, std::move(opts));
    return text.starts_with('\n') ? text.substr(1) : text;
}

std::string HelpFormatter::make_usage(const CLI::App* app, std::string name) const {
    std::string usage = CLI::Formatter::make_usage(app, std::move(name));
    while (!usage.empty() && usage.back() == '\n') usage.pop_back();
    return usage + " [-- SUMO-OPTION...]\n\n";
}

std::string HelpFormatter::make_option_opts(const CLI::Option* option) const {
    // Only the value's name: defaults go to the text, repetition and exclusions are written there.
    if (option->get_type_size() == 0) return {};
    return " " + option->get_type_name();
}

std::string HelpFormatter::make_option_desc(const CLI::Option* option) const {
    const std::string& fallback = option->get_default_str();
    if (fallback.empty()) return option->get_description();
    return fmt::format("{} (default: {})", option->get_description(), fallback);
}

}  // namespace sbsim::app
