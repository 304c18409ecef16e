#include "cli_conventions.hpp"

#include <cstdio>

#include <CLI/CLI.hpp>

#include "core/schema.hpp"
#include "core/version.hpp"

namespace maris::cli {

namespace {

// "maris-cli run" for the sub-command run of maris-cli.
std::string commandPath(const CLI::App& app) {
  return app.get_parent() ? commandPath(*app.get_parent()) + " " + app.get_name() : app.get_name();
}

// The sub-command the parser went deepest into (the application itself if none).
const CLI::App& innermost(const CLI::App& app) {
  const auto chosen = app.get_subcommands();
  return chosen.empty() ? app : innermost(*chosen.front());
}

void addOptionNames(const CLI::App& app, std::vector<std::string>& names) {
  for (const CLI::Option* option : app.get_options()) {
    for (const auto& n : option->get_lnames()) names.push_back("--" + n);
    for (const auto& n : option->get_snames()) names.push_back("-" + n);
  }
}

std::vector<std::string> visibleCommands(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); }))
    names.push_back(sub->get_name());
  return names;
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const auto& w : words) text += (text.empty() ? "" : ", ") + w;
  return text;
}

std::string guessSuffix(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string guess = didYouMean(word, candidates);
  return guess.empty() ? std::string() : "; did you mean " + guess + "?";
}

// The first argument that nothing took, named: an unknown option, an unknown sub-command, or an
// argument too many. Empty if every argument was taken.
std::string describeLeftOver(const CLI::App& app, const CLI::App& deepest) {
  const std::vector<std::string> left = app.remaining(true);
  if (left.empty()) return {};
  const std::string& first = left.front();
  if (first.size() > 1 && first[0] == '-') {
    std::vector<std::string> options;
    addOptionNames(deepest, options);
    if (&deepest != &app) addOptionNames(app, options);
    return "unknown option " + first + guessSuffix(first.substr(0, first.find('=')), options);
  }
  if (deepest.get_require_subcommand_min() > 0) {  // `maris-cli frob`, `maris-cli study frob`
    const auto commands = visibleCommands(deepest);
    return "unknown command '" + first + "'" + guessSuffix(first, commands) + " (the commands: " + joined(commands) + ")";
  }
  return "unexpected extra argument '" + first + "'";
}

// CLI11's message for an error that is not a left-over argument, in the project's words where it helps.
std::string describeParseError(const CLI::ParseError& error, const CLI::App& deepest) {
  const std::string what = error.what();
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
    // CLI11: "--out: 1 required DIR missing".
    const std::string name = what.substr(0, what.find(':'));
    if (!name.empty() && name[0] == '-') {
      const CLI::Option* option = deepest.get_option_no_throw(name);
      const std::string type = option ? option->get_type_name() : std::string();
      return name + " needs a value" + (type.empty() ? std::string() : " (" + type + ")");
    }
  }
  if (dynamic_cast<const CLI::RequiredError*>(&error) && deepest.get_require_subcommand_min() > 0 &&
      deepest.get_subcommands().empty())
    return "a command is required (the commands: " + joined(visibleCommands(deepest)) + ")";
  return what;
}

}  // namespace

std::string versionLine(std::string_view program) { return std::string(program) + " " + versionText(); }

std::string exitCodesHelp(bool cancellable) {
  std::string text =
      "Exit codes:\n"
      "  0    success\n"
      "  1    usage error: an unknown option or command, a missing value, an extra argument, a bad value\n"
      "  2    invalid input: a scenario that does not load or validate (each bad field is named)\n"
      "  3    solver failure (the step and quantity are named)\n";
  if (cancellable)
    text +=
        "  130  cancelled by SIGINT (Ctrl-C); nothing is written for that run\n"
        "  143  cancelled by SIGTERM; nothing is written for that run\n";
  return text;
}

void applyConventions(CLI::App& app, bool cancellable) {
  app.set_help_flag("-h,--help", "print this help and exit");
  app.set_version_flag("--version", versionLine(app.get_name()), "print the version and exit");
  app.footer(exitCodesHelp(cancellable));
  app.allow_extras();  // parseArguments names what is left over, with a did-you-mean
  app.fallthrough();   // the program's own options (--version) also after a sub-command
  app.get_formatter()->column_width(34);
}

ParseOutcome parseArguments(CLI::App& app, const std::vector<std::string>& arguments) {
  ParseOutcome outcome;
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 takes them last first
  std::string error;
  try {
    app.parse(reversed);
    error = describeLeftOver(app, innermost(app));
  } catch (const CLI::CallForHelp&) {
    outcome.exit_code = kExitOk;
    outcome.output = app.help();
    return outcome;
  } catch (const CLI::CallForVersion& version) {
    outcome.exit_code = kExitOk;
    outcome.output = std::string(version.what()) + "\n";
    return outcome;
  } catch (const CLI::ParseError& e) {
    // An argument nothing took explains the failure better than what it caused ("a command is required").
    error = describeLeftOver(app, innermost(app));
    if (error.empty()) error = describeParseError(e, innermost(app));
    if (arguments.empty()) outcome.output = app.help();
  }
  if (!error.empty()) {
    outcome.exit_code = kExitUsage;
    outcome.command = commandPath(innermost(app));
    outcome.error = error;
  }
  return outcome;
}

std::string usageErrorText(std::string_view command, std::string_view error) {
  const std::string name(command);
  return name + ": " + std::string(error) + " (see " + name + " --help)\n";
}

int reportOutcome(const ParseOutcome& outcome) {
  if (!outcome.error.empty()) std::fputs(usageErrorText(outcome.command, outcome.error).c_str(), stderr);
  if (!outcome.output.empty()) std::fputs(outcome.output.c_str(), outcome.exit_code == kExitOk ? stdout : stderr);
  return outcome.exit_code.value_or(kExitOk);
}

}  // namespace maris::cli
