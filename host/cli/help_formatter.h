#pragma once
// CLI11's help, wrapped to kHelpWidth columns: every option's and command's description flows in
// its own column, and descriptions and footers are wrapped at word boundaries.

#include <cstddef>
#include <string>

#include <CLI/CLI.hpp>

namespace hexray::cli {

inline constexpr std::size_t kHelpWidth = 100;

// `text` wrapped to `width` columns at spaces. Its own line breaks are kept; a line's
// continuations are indented as deep as the line itself plus `hangingIndent`, and the first line
// of all starts `firstColumn` columns in (what precedes it on the screen).
std::string wrapText(const std::string& text, std::size_t width, std::size_t firstColumn = 0,
                     std::size_t hangingIndent = 0);

class HelpFormatter : public CLI::Formatter {
public:
    HelpFormatter();
    std::string make_option(const CLI::Option* option, bool isPositional) const override;
    std::string make_subcommand(const CLI::App* command) const override;
    std::string make_description(const CLI::App* app) const override;
    std::string make_footer(const CLI::App* app) const override;

private:
    // "  NAME   description", the description wrapped in the column right of the names.
    std::string nameAndDescription(const std::string& name, const std::string& description) const;
};

// "hexray render [OPTIONS] scenes...": how a command is used, as its help's Usage line says.
std::string usageOf(const CLI::App& command);

}  // namespace hexray::cli
