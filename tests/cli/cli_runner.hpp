// Runs maris-cli as a child process and captures its exit code, stdout and stderr.
#pragma once

#include <string>
#include <vector>

namespace maris::test {

// The built-in scenario tests run when what they check is the run folder, the summary or the command
// line rather than the physics: a cantilever under a tip load, statics only (milliseconds in Release,
// under a second under the sanitizers, where the default scenario's dynamics take half a minute).
inline constexpr const char* kQuickBuiltin = "riser_cantilever_tip_load";

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
  double exit_after_signal_s = -1;  // [s] from the signal to the process's end (-1: no signal sent)
};

// Runs the build's maris-cli (maris::test::cliPath) with `args` in `working_dir`. If interrupt_after_s > 0, sends `signal` after
// that many seconds (to test cancellation). `shell_prefix` runs in the wrapper shell before the exec
// (e.g. "ulimit -f 8;").
CliResult runCli(const std::vector<std::string>& args, const std::string& working_dir = ".",
                 double interrupt_after_s = 0.0, int signal = 2, const std::string& shell_prefix = "");

}  // namespace maris::test
