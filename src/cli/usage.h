// The command line described from its parser (the CLI11 app that cli.cc builds), so that the
// parser is the one owner of its grammar: the synopsis lines (`drape help`, the usage printed
// after a usage error, docs/reference.md's "The command line", which a test holds against them),
// the bash completion script, and the "did you mean" for an unknown command or option.
#ifndef DRAPE_SRC_CLI_USAGE_H_
#define DRAPE_SRC_CLI_USAGE_H_

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace drape {

// Every subcommand of `app`, in the order they were added.
std::vector<const CLI::App*> AllSubcommands(const CLI::App& app);

// One command's synopsis: "drape solve [--solver NAME] [-o|--out DIR] ... [--] SCENE.yaml", each
// option with its value's name (its CLI11 type name), repeatable ones followed by "...".
std::string CommandSynopsis(const CLI::App& command);

// Every command's synopsis, one a line, then "drape help [COMMAND] | --help | --version".
std::string Synopsis(const CLI::App& app);

// "unknown command 'sovle'; did you mean 'solve'?": `name` among `app`'s subcommands.
std::string UnknownCommandText(const CLI::App& app, const std::string& name);

// The subcommand that `args` name (their first word when it is one), or null.
const CLI::App* NamedCommand(const CLI::App& app, const std::vector<std::string>& args);

// What is wrong when `args` name an unknown command, or give the command named an option it does
// not have ("unknown command 'solv'; did you mean 'solve'?", "unknown option '--solvr' of `drape
// solve`; did you mean '--solver'?"); nothing when every word is known (CLI11 checks the rest).
std::optional<std::string> UnknownWord(const CLI::App& app, const std::vector<std::string>& args);

// The bash completion script: the subcommands, each one's options, the values of --solver,
// --solvers and --method, and file names for the rest.
std::string BashCompletion(const CLI::App& app);

}  // namespace drape

#endif  // DRAPE_SRC_CLI_USAGE_H_
