#include "cli/help_formatter.h"

#include <sstream>
#include <vector>

namespace hexray::cli {
namespace {

constexpr std::size_t kNameColumns = 30;

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

// One of the text's own lines, wrapped at spaces (runs of them kept, as in a table): it starts
// `column` columns in, and its continuations are indented as deep as it is, plus `hangingIndent`
// when it is indented at all (a list's entry).
std::string wrapLine(const std::string& line, std::size_t width, std::size_t column, std::size_t hangingIndent) {
    const std::size_t leading = line.find_first_not_of(' ');
    if (leading == std::string::npos) {
        return "";
    }
    const std::size_t indent = column + leading + (leading > 0 ? hangingIndent : 0);
    std::string out(leading, ' ');
    column += leading;
    bool lineStart = true;
    std::istringstream words(line.substr(leading));
    for (std::string word; std::getline(words, word, ' ');) {  // an empty word: one more space
        if (!lineStart && !word.empty() && column + 1 + word.size() > width) {
            out.erase(out.find_last_not_of(' ') + 1);
            out += "\n" + std::string(indent, ' ');
            column = indent;
            lineStart = true;
        }
        if (!lineStart) {
            out += ' ';
            ++column;
        }
        out += word;
        column += word.size();
        lineStart = false;
    }
    return out;
}

}  // namespace

std::string wrapText(const std::string& text, std::size_t width, std::size_t firstColumn, std::size_t hangingIndent) {
    std::string out;
    const std::vector<std::string> lines = splitLines(text);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (i > 0) {
            out += "\n" + (lines[i].empty() ? std::string() : std::string(firstColumn, ' '));
        }
        out += wrapLine(lines[i], width, firstColumn, hangingIndent);
    }
    return out;
}

HelpFormatter::HelpFormatter() {
    column_width(kNameColumns);
}

std::string HelpFormatter::nameAndDescription(const std::string& name, const std::string& description) const {
    std::string out = "  " + name;
    if (description.empty()) {
        return out + "\n";
    }
    if (out.size() + 1 > kNameColumns) {
        out += "\n" + std::string(kNameColumns, ' ');
    } else {
        out.resize(kNameColumns, ' ');
    }
    return out + wrapText(description, kHelpWidth, kNameColumns) + "\n";
}

std::string HelpFormatter::make_option(const CLI::Option* option, bool isPositional) const {
    return nameAndDescription(make_option_name(option, isPositional) + make_option_opts(option),
                              make_option_desc(option));
}

std::string HelpFormatter::make_subcommand(const CLI::App* command) const {
    return nameAndDescription(command->get_display_name(true), command->get_description());
}

std::string HelpFormatter::make_description(const CLI::App* app) const {
    const std::string description = app->get_description();
    return description.empty() ? std::string() : wrapText(description, kHelpWidth) + "\n";
}

std::string HelpFormatter::make_footer(const CLI::App* app) const {
    const std::string footer = app->get_footer();
    return footer.empty() ? std::string() : wrapText(footer, kHelpWidth, 0, 3) + "\n";
}

std::string usageOf(const CLI::App& command) {
    const std::string name = command.get_parent() ? "hexray " + command.get_name() : "hexray";
    std::string usage = HelpFormatter().make_usage(&command, name);
    const std::size_t colon = usage.find(": ");
    usage = colon == std::string::npos ? usage : usage.substr(colon + 2);
    while (!usage.empty() && usage.back() == '\n') {
        usage.pop_back();
    }
    return usage;
}

}  // namespace hexray::cli
