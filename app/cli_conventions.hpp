// What maris-cli and maris share on the command line: exit codes, the --version line, the help footer,
// and how a command line is parsed with CLI11 and how a usage error reads. One set of conventions:
//   --help/-h (also after a sub-command) prints the generated help, exit 0;
//   --version prints "PROGRAM 0.1.0 (git 1a2b3c4)", exit 0;
//   an unknown option or sub-command, a missing value or an extra argument is a usage error, exit 1:
//   "maris-cli run: unknown option --sett; did you mean --set? (see maris-cli run --help)".
// No Qt here: maris answers its options before Qt starts.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
}

namespace maris::cli {

// The exit codes of both executables (README "The command line").
enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 1,           // a bad option, sub-command or option value (also an unexpected internal error)
  kExitInvalidInput = 2,    // a scenario that does not load or validate; every bad field is named
  kExitSolverFailure = 3,   // the solver failed; the step and quantity are named
  kExitInterrupted = 130,   // cancelled by SIGINT (128 + 2), nothing written for that run
  kExitTerminated = 143,    // cancelled by SIGTERM (128 + 15), nothing written for that run
};

// "maris-cli 0.1.0 (git 1a2b3c4)": the program's name and maris::versionText().
std::string versionLine(std::string_view program);

// The exit codes as lines for the end of --help; `cancellable`: a run can be cancelled by a signal
// (maris-cli), so 130 and 143 are listed too.
std::string exitCodesHelp(bool cancellable);

// Gives a CLI11 application (before its sub-commands are added, which inherit it) the shared
// conventions: --help/-h, --version, the exit codes as footer, unknown arguments kept for
// parseArguments to name.
void applyConventions(CLI::App& app, bool cancellable);

// What parsing decided: go on (no exit code), or stop with `exit_code` after printing `output` (help,
// version) on stdout or usageErrorText(command, error) on stderr.
struct ParseOutcome {
  std::optional<int> exit_code;
  std::string output;
  std::string command;  // the (sub-)command the error belongs to: "maris-cli run"
  std::string error;    // what is wrong, naming the option, sub-command or argument
};

// Parses `arguments` (without the program's name) into `app`'s options.
ParseOutcome parseArguments(CLI::App& app, const std::vector<std::string>& arguments);

// One usage error on one line: "maris-cli run: --out needs a value (DIR) (see maris-cli run --help)".
std::string usageErrorText(std::string_view command, std::string_view error);

// Prints the outcome (help or version on stdout, a usage error on stderr); returns its exit code.
int reportOutcome(const ParseOutcome& outcome);

}  // namespace maris::cli
