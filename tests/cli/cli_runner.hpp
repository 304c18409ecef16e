// Runs maris-cli as a child process and captures its exit code, stdout and stderr.
#pragma once

#include <string>
#include <vector>

namespace maris::test {

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
  double exit_after_signal_s = -1;  // [s] from the signal to the process's end (-1: no signal sent)
};

// Runs MARIS_CLI_PATH with `args` in `working_dir`. If interrupt_after_s > 0, sends `signal` after
// that many seconds (to test cancellation). `shell_prefix` runs in the wrapper shell before the exec
// (e.g. "ulimit -f 8;").
CliResult runCli(const std::vector<std::string>& args, const std::string& working_dir = ".",
                 double interrupt_after_s = 0.0, int signal = 2, const std::string& shell_prefix = "");

}  // namespace maris::test
