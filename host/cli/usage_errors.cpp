#include "cli/usage_errors.h"

#include <regex>
#include <vector>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/help_formatter.h"
#include "util/closest_name.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

// The subcommand named on the command line, or hexray itself.
const CLI::App& commandGiven(const CLI::App& app) {
    const std::vector<CLI::App*> given = app.get_subcommands();
    return given.empty() ? app : *given.front();
}

// "render" or "hexray": how messages name the command.
std::string commandName(const CLI::App& command) {
    return command.get_parent() ? command.get_name() : "hexray";
}

std::string helpCommand(const CLI::App& command) {
    return command.get_parent() ? "hexray " + command.get_name() + " --help" : "hexray --help";
}

// Every option name a command accepts: its own and, after it, hexray's global ones.
std::vector<std::string> optionNames(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::App* app = &command; app; app = app->get_parent()) {
        for (const CLI::Option* option : app->get_options()) {
            for (const std::string& name : option->get_lnames()) {
                names.push_back("--" + name);
            }
            for (const std::string& name : option->get_snames()) {
                names.push_back("-" + name);
            }
        }
    }
    return names;
}

std::string unexpectedWordMessage(const CLI::App& command, const std::string& word) {
    const std::string name = commandName(command);
    if (word.size() < 2 || word[0] != '-') {
        return "unexpected argument '" + printable(word) + "' for " + name + " (usage: " + usageOf(command) + ")";
    }
    const std::string option = word.substr(0, word.find('='));
    const std::string where = command.get_parent() ? " for " + name : "";
    const std::optional<std::string> near = closestName(option, optionNames(command));
    const std::string hint = "(" + helpCommand(command) + " describes the options)";
    if (near) {
        return "unknown option '" + printable(option) + "'" + where + "; did you mean " + *near + "? " + hint;
    }
    return "unknown option '" + printable(option) + "'" + where + " " + hint;
}

std::string missingArgumentMessage(const CLI::App& command, const CLI::ParseError& error) {
    const std::vector<const CLI::Option*> missing =
        command.get_options([](const CLI::Option* option) { return option->get_required() && option->count() == 0; });
    if (missing.empty()) {
        return error.what();
    }
    const CLI::Option& option = *missing.front();
    const std::string what = option.get_positional() ? "its " + option.get_name() + " argument" : option.get_name();
    return commandName(command) + " needs " + what + " (usage: " + usageOf(command) + ")";
}

// CLI11's "--width: 1 required INT missing": an option given without its value.
std::optional<std::string> valueMissingMessage(const CLI::App& command, const std::string& text) {
    static const std::regex valueMissing(R"(^(\S+): \d+ required .* missing$)");
    std::smatch match;
    if (!std::regex_match(text, match, valueMissing)) {
        return std::nullopt;
    }
    return match[1].str() + " needs a value (" + helpCommand(command) + " describes it)";
}

// CLI11's "--all excludes --precision".
std::optional<std::string> excludedMessage(const std::string& text) {
    static const std::regex excludes(R"(^(\S+) excludes (\S+)$)");
    std::smatch match;
    if (!std::regex_match(text, match, excludes)) {
        return std::nullopt;
    }
    return match[1].str() + " and " + match[2].str() + " cannot be given together";
}

// An unknown word is named first, whatever CLI11 threw: "pixel scene.json --widht 8 1" takes 8 for
// x and misses y, but the mistake is --widht.
std::string messageFor(const CLI::App& app, const CLI::ParseError& error) {
    const CLI::App& command = commandGiven(app);
    if (const std::vector<std::string> extras = app.remaining(true); !extras.empty()) {
        return unexpectedWordMessage(command, extras.front());
    }
    if (dynamic_cast<const CLI::RequiredError*>(&error)) {
        return missingArgumentMessage(command, error);
    }
    const std::string text = error.what();
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
        return valueMissingMessage(command, text).value_or(text);
    }
    if (dynamic_cast<const CLI::ExcludesError*>(&error)) {
        return excludedMessage(text).value_or(text);
    }
    return text;
}

}  // namespace

int reportParseError(CLI::App& app, const CLI::ParseError& error) {
    if (dynamic_cast<const CLI::CallForHelp*>(&error) || dynamic_cast<const CLI::CallForAllHelp*>(&error)) {
        return app.exit(error) == 0 ? kSuccess : kBadInput;
    }
    if (dynamic_cast<const CLI::RequiredError*>(&error) && app.get_subcommands().empty() &&
        app.remaining(true).empty()) {
        printError(std::string("a command is required: ") + kCommandNames + " (hexray --help describes them)");
        return kBadInput;
    }
    printError(messageFor(app, error));
    return kBadInput;
}

std::optional<std::string> unknownCommandMessage(int argc, char** argv, const CLI::App& app) {
    for (int i = 1; i < argc; ++i) {
        const std::string word = argv[i];
        if (word == "--") {
            return std::nullopt;
        }
        if (word.empty() || word[0] == '-') {
            continue;
        }
        std::vector<std::string> commands;
        for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
            if (command->check_name(word)) {
                return std::nullopt;
            }
            commands.push_back(command->get_name());
        }
        if (const std::optional<std::string> near = closestName(word, commands)) {
            return "unknown command '" + printable(word) + "'; did you mean " + *near +
                   "? (hexray --help describes the commands)";
        }
        return "unknown command '" + printable(word) + "' (the commands are " + kCommandNames +
               "; hexray --help describes them)";
    }
    return std::nullopt;
}

}  // namespace hexray::cli
