#include "cli_runner.hpp"

#include <chrono>
#include <csignal>
#include <thread>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include "source_tree.hpp"
#include "study_cli_helpers.hpp"

extern char** environ;

namespace maris::test {

CliResult runCli(const std::vector<std::string>& args, const std::string& working_dir, double interrupt_after_s,
                 int signal, const std::string& shell_prefix) {
  static int counter = 0;
  const std::string base = "/tmp/maris_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
  const std::string out_file = base + ".out", err_file = base + ".err";
  // A tiny shell wrapper changes directory and redirects, keeping the spawn portable.
  std::string command = "cd '" + working_dir + "' && " + shell_prefix + " exec '" + maris::test::cliPath() + "'";
  for (const auto& a : args) {
    std::string quoted;
    for (char c : a) quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    command += " '" + quoted + "'";
  }
  command += " >'" + out_file + "' 2>'" + err_file + "' </dev/null";
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  pid_t pid = 0;
  CliResult result;
  if (::posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ) != 0) return result;
  std::chrono::steady_clock::time_point signalled;
  if (interrupt_after_s > 0.0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(interrupt_after_s));
    signalled = std::chrono::steady_clock::now();
    ::kill(pid, signal);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (interrupt_after_s > 0.0)
    result.exit_after_signal_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status)) result.exit_code = 128 + WTERMSIG(status);
  result.out = slurp(out_file);
  result.err = slurp(err_file);
  ::unlink(out_file.c_str());
  ::unlink(err_file.c_str());
  return result;
}

}  // namespace maris::test
