// Runs maris-cli as a child process and captures its exit code, stdout and stderr.
#pragma once

#include <string>
#include <vector>

namespace maris::test {

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs MARIS_CLI_PATH with `args` in `working_dir`. If interrupt_after_s > 0, sends SIGINT after
// that many seconds (to test cancellation).
CliResult runCli(const std::vector<std::string>& args, const std::string& working_dir = ".",
                 double interrupt_after_s = 0.0);

}  // namespace maris::test
