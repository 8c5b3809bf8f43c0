#include "apps/usage_errors.h"

#include <algorithm>
#include <cstdio>

namespace eikon::app {
namespace {

size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// The deepest command the parse reached ("render", "bench smoke"): CLI11 keeps those it parsed.
CLI::App* deepestCommand(CLI::App& app) {
    CLI::App* at = &app;
    for (;;) {
        const std::vector<CLI::App*> parsed = at->get_subcommands();
        if (parsed.empty()) return at;
        at = parsed.front();
    }
}

std::string commandPath(const CLI::App& app, const CLI::App* cmd) {
    std::string path;
    for (const CLI::App* at = cmd; at != nullptr && at != &app; at = at->get_parent())
        path = at->get_name() + (path.empty() ? "" : " " + path);
    return path;
}

std::vector<std::string> subcommandNames(const CLI::App& cmd) {
    std::vector<std::string> names;
    for (const CLI::App* sub : cmd.get_subcommands([](const CLI::App*) { return true; }))
        names.push_back(sub->get_name());
    return names;
}

std::vector<std::string> optionNames(const CLI::App& cmd) {
    std::vector<std::string> names;
    for (const CLI::Option* opt : cmd.get_options()) {
        for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
        for (const std::string& s : opt->get_snames()) names.push_back("-" + s);
    }
    return names;
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

void printLine(const std::string& where, const std::string& reason) {
    std::fprintf(stderr, "eikon: %s: %s\n", where.c_str(), reason.c_str());
}

// The arguments CLI11 did not expect, from its message "The following argument(s) was/were not
// expected: a b".
std::vector<std::string> extrasOf(const CLI::ParseError& e) {
    std::vector<std::string> extras;
    const std::string message = e.what();
    const size_t colon = message.find(": ");
    if (colon == std::string::npos) return extras;
    std::string rest = message.substr(colon + 2);
    for (size_t start = 0; start < rest.size();) {
        size_t end = rest.find(' ', start);
        if (end == std::string::npos) end = rest.size();
        if (end > start) extras.push_back(rest.substr(start, end - start));
        start = end + 1;
    }
    return extras;
}

// The first argument after the commands parsed that is not an option: where an unknown
// subcommand stands ("eikon rendr", "eikon bench smok").
std::string unknownCommand(const CLI::App& cmd, int argc, char** argv, int depth) {
    if (subcommandNames(cmd).empty() || depth + 1 >= argc) return "";
    const std::string word = argv[depth + 1];
    if (word.empty() || word[0] == '-') return "";
    return word;
}

}  // namespace

std::string closestName(const std::string& given, const std::vector<std::string>& known) {
    std::string best;
    size_t bestDistance = 3;
    for (const std::string& name : known) {
        const bool prefix = name.size() > 2 && given.size() > 2 &&
                            (name.rfind(given, 0) == 0 || given.rfind(name, 0) == 0);
        const size_t d = prefix ? 1 : editDistance(given, name);
        if (d < bestDistance) {
            bestDistance = d;
            best = name;
        }
    }
    return best;
}

int reportParseError(CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
    // --help and --version: their text, exit 0 (CLI11 prints them).
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    CLI::App* cmd = deepestCommand(app);
    const std::string path = commandPath(app, cmd);
    int depth = 0;
    for (const CLI::App* at = cmd; at != &app; at = at->get_parent()) ++depth;
    const std::string help = "eikon " + (path.empty() ? "" : path + " ") + "--help";

    // A word where a command belongs that names none: the commands, and the closest.
    const std::string word = unknownCommand(*cmd, argc, argv, depth);
    const std::vector<std::string> commands = subcommandNames(*cmd);
    if (!word.empty() && std::find(commands.begin(), commands.end(), word) == commands.end()) {
        const std::string guess = closestName(word, commands);
        printLine(word, "unknown command" +
                            (guess.empty() ? "" : "; did you mean '" + guess + "'?") + " (" +
                            (path.empty() ? "" : path + " ") + "commands: " + joined(commands) +
                            ")");
        return kExitUsage;
    }
    if (!commands.empty() && dynamic_cast<const CLI::RequiredError*>(&e) != nullptr &&
        cmd->get_subcommands().empty()) {
        printLine(path.empty() ? "eikon" : path,
                  "a command is required: " + joined(commands) + " (" + help + ")");
        return kExitUsage;
    }
    const std::string where = path.empty() ? "eikon" : path;
    if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
        // An unknown option first: the value after it ("--sise 64x48") is only stray because
        // of it.
        const std::vector<std::string> extras = extrasOf(e);
        for (const std::string& extra : extras) {
            if (extra.size() < 2 || extra[0] != '-') continue;
            // "--size=64x48": the option's name is before '='.
            const std::string name = extra.substr(0, extra.find('='));
            const std::string guess = closestName(name, optionNames(*cmd));
            printLine(where, name + ": unknown option" +
                                 (guess.empty() ? "" : "; did you mean " + guess + "?") + " (" +
                                 help + ")");
            return kExitUsage;
        }
        if (!extras.empty()) {
            printLine(where, "'" + extras.front() + "': unexpected argument (" + help + ")");
            return kExitUsage;
        }
    }
    printLine(where, oneLine(e.what()) + " (" + help + ")");
    return kExitUsage;
}

}  // namespace eikon::app
