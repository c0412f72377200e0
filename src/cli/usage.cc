#include "src/cli/usage.h"

#include <algorithm>
#include <cstdlib>

#include "src/fit/fit_methods.h"
#include "src/scene/yaml_reader.h"
#include "src/solvers/solver.h"

namespace drape {

namespace {

// The option names of `command` (--long and -s), without its positionals.
std::string OptionWords(const CLI::App& command) {
  std::string words;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames())
      words += (words.empty() ? "--" : " --") + name;
    for (const std::string& name : option->get_snames())
      words += (words.empty() ? "-" : " -") + name;
  }
  return words;
}

std::string Joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : " ") + word;
  return text;
}

// The values an option takes, where drape has their list: methods, fit methods, shells.
std::string OptionValueCases() {
  std::vector<std::string> solvers;
  for (const SolverInfo& solver : AllSolvers()) solvers.push_back(solver.name);
  return "      --solver) COMPREPLY=($(compgen -W \"" + Joined(solvers) +
         "\" -- \"$cur\")); return ;;\n"
         "      --solvers) COMPREPLY=($(compgen -W \"all " +
         Joined(solvers) +
         "\" -- \"$cur\")); return ;;\n"
         "      --method) COMPREPLY=($(compgen -W \"" +
         Joined(FitMethods()) + "\" -- \"$cur\")); return ;;\n";
}

// The option's names as a synopsis writes them: "--solver", "-o|--out".
std::string OptionNames(const CLI::Option& option) {
  std::string names;
  for (const std::string& name : option.get_snames()) names += (names.empty() ? "-" : "|-") + name;
  for (const std::string& name : option.get_lnames()) {
    names += (names.empty() ? "--" : "|--") + name;
  }
  return names;
}

// "[--solver NAME]", "[--no-plots]", "[--task-id [I]]"; a positional: "SCENE.yaml", "[COMMAND]".
std::string OptionSynopsis(const CLI::Option& option) {
  const std::string full = option.get_type_name();  // "N:INT in [1 - 10000]": the validator's after
  const std::string value = full.substr(0, full.find(':'));
  if (option.get_positional()) return option.get_required() ? value : "[" + value + "]";
  std::string text = OptionNames(option);
  if (option.get_expected_max() > 0) {
    text += option.get_expected_min() == 0 ? " [" + value + "]" : " " + value;
  }
  return "[" + text + "]";
}

// Numbers are values, not options ("--only -1" is CLI11's to refuse).
bool IsNumber(const std::string& word) {
  char* end = nullptr;
  std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0';
}

// The unknown option among `words` (a command's arguments), with the nearest known one.
std::optional<std::string> UnknownOption(const CLI::App& command,
                                         const std::vector<std::string>& words) {
  std::vector<std::string> known;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) known.push_back("--" + name);
    for (const std::string& name : option->get_snames()) known.push_back("-" + name);
  }
  for (const std::string& word : words) {
    if (word == "--") break;
    if (word.size() < 2 || word[0] != '-' || IsNumber(word)) continue;
    const std::string name = word.substr(0, word.find('='));
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    return "unknown option '" + name + "' of `drape " + command.get_name() + "`" +
           SuggestionText(name, known);
  }
  return std::nullopt;
}

}  // namespace

// Every subcommand of `app`, parsed or not, in the order they were added.
std::vector<const CLI::App*> AllSubcommands(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App*) { return true; });
}

std::string CommandSynopsis(const CLI::App& command) {
  std::string options, positionals;
  for (const CLI::Option* option : command.get_options()) {
    if (option == command.get_help_ptr()) continue;
    std::string& part = option->get_positional() ? positionals : options;
    part += " " + OptionSynopsis(*option);
  }
  const bool separator = !options.empty() && !positionals.empty();
  return "drape " + command.get_name() + options + (separator ? " [--]" : "") + positionals;
}

std::string Synopsis(const CLI::App& app) {
  std::string text;
  for (const CLI::App* command : AllSubcommands(app)) {
    if (command->get_name() != "help") text += CommandSynopsis(*command) + "\n";
  }
  return text + "drape help [COMMAND] | --help | --version\n";
}

std::string UnknownCommandText(const CLI::App& app, const std::string& name) {
  std::vector<std::string> names;
  for (const CLI::App* known : AllSubcommands(app)) names.push_back(known->get_name());
  return "unknown command '" + name + "'" + SuggestionText(name, names);
}

const CLI::App* NamedCommand(const CLI::App& app, const std::vector<std::string>& args) {
  if (args.empty()) return nullptr;
  for (const CLI::App* command : AllSubcommands(app)) {
    if (command->get_name() == args[0]) return command;
  }
  return nullptr;
}

std::optional<std::string> UnknownWord(const CLI::App& app, const std::vector<std::string>& args) {
  if (args.empty() || args[0].empty() || args[0][0] == '-') return std::nullopt;
  const CLI::App* command = NamedCommand(app, args);
  if (!command) return UnknownCommandText(app, args[0]);
  return UnknownOption(*command, std::vector<std::string>(args.begin() + 1, args.end()));
}

// The bash completion script, generated from the parser itself (so it lists exactly the
// subcommands and options that `drape` accepts): subcommands first, then per subcommand its
// options, the values of --solver, --solvers and --method, and file names for the rest.
std::string BashCompletion(const CLI::App& app) {
  std::string commands, cases;
  for (const CLI::App* command : AllSubcommands(app)) {
    const std::string& name = command->get_name();
    commands += (commands.empty() ? "" : " ") + name;
    std::string words = OptionWords(*command);
    if (name == "completion") words += " bash";
    cases += "    " + name + ") words=\"" + words + "\" ;;\n";
  }
  return "# bash completion for drape, generated by `drape completion bash`\n"
         "_drape() {\n"
         "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
         "  local command=\"\" i words\n"
         "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
         "    case \" " +
         commands +
         " \" in\n"
         "      *\" ${COMP_WORDS[i]} \"*) command=\"${COMP_WORDS[i]}\"; break ;;\n"
         "    esac\n"
         "  done\n"
         "  if [[ -z \"$command\" ]]; then\n"
         "    COMPREPLY=($(compgen -W \"" +
         commands + " " + OptionWords(app) +
         "\" -- \"$cur\"))\n"
         "    return\n"
         "  fi\n"
         "  case \"$prev\" in\n" +
         OptionValueCases() +
         "  esac\n"
         "  case \"$command\" in\n" +
         cases +
         "  esac\n"
         "  if [[ \"$cur\" == -* || \"$command\" == completion ]]; then\n"
         "    COMPREPLY=($(compgen -W \"$words\" -- \"$cur\"))\n"
         "  else\n"
         "    COMPREPLY=($(compgen -f -- \"$cur\"))\n"
         "  fi\n"
         "}\n"
         "complete -o filenames -o bashdefault -F _drape drape\n";
}

}  // namespace drape
