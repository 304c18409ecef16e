// `maris-cli study submit --engine slurm`: the case files, an sbatch job array whose tasks each run a
// block of cases (`maris-cli study run-cases`), and a collect job that runs after the array however its
// tasks end (--dependency=afterany). Maris schedules nothing itself: Slurm does.
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "cli_conventions.hpp"
#include "cli_study_internal.hpp"
#include "core/scenario.hpp"
#include "core/text_format.hpp"

extern char** environ;

namespace maris::cli {

namespace {

using namespace maris::study;

// 'text' for a POSIX shell.
std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

// Runs `args` (found on PATH) and captures stdout and stderr through files in `scratch`.
CommandResult runCommand(const std::vector<std::string>& args, const std::filesystem::path& scratch) {
  const std::string out_file = (scratch / ".sbatch.out").string(), err_file = (scratch / ".sbatch.err").string();
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, STDERR_FILENO, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  CommandResult result;
  pid_t pid = 0;
  const int error = ::posix_spawnp(&pid, argv[0], &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (error != 0) {
    result.err = args[0] + " cannot be started: " + std::strerror(error);
    return result;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = readTextFile(out_file);
  result.err = readTextFile(err_file);
  std::filesystem::remove(out_file);
  std::filesystem::remove(err_file);
  return result;
}

// The #SBATCH lines every job of the study shares.
std::string commonDirectives(const StudyOptions& o) {
  std::string text;
  if (!o.partition.empty()) text += "#SBATCH --partition=" + o.partition + "\n";
  if (!o.account.empty()) text += "#SBATCH --account=" + o.account + "\n";
  if (!o.time.empty()) text += "#SBATCH --time=" + o.time + "\n";
  if (!o.mem.empty()) text += "#SBATCH --mem=" + o.mem + "\n";
  return text;
}

std::string jobName(const std::string& name) {
  std::string safe;
  for (char c : name) safe += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return "maris-" + safe.substr(0, 40);
}

}  // namespace

void addSubmitOptions(CLI::App& submit, StudyOptions& o) {
  submit.add_option("STUDY", o.study_file, "a study file (see `maris-cli schema study`)")->required()->type_name("");
  submit.add_option("--out", o.out_dir, "the study's folder, shared by the cluster's nodes")->required()->type_name("DIR");
  submit.add_option("--engine", o.engine, "the scheduler (slurm)")
      ->required()
      ->type_name("ENGINE")
      ->check(CLI::IsMember({"slurm"}));
  submit.add_option("--partition", o.partition, "sbatch --partition")->type_name("P");
  submit.add_option("--account", o.account, "sbatch --account")->type_name("A");
  submit.add_option("--time", o.time, "sbatch --time of each array task, e.g. 01:00:00")->type_name("T");
  submit.add_option("--mem", o.mem, "sbatch --mem of each array task, e.g. 4G")->type_name("M");
  submit.add_option("--max-parallel", o.max_parallel, "array tasks running at once (the %K of --array)")
      ->type_name("K")
      ->check(CLI::Range(1u, 100000u));
  submit.add_option("--cases-per-task", o.cases_per_task, "cases each array task runs (default 1)")
      ->type_name("C")
      ->check(CLI::Range(1u, 100000u));
  submit.add_option("--cpus-per-task", o.cpus_per_task, "sbatch --cpus-per-task; a task runs as many cases at once")
      ->type_name("N")
      ->check(CLI::Range(1u, 4096u));
  submit.add_option("--timeout", o.timeout_s, "stop a case after this many seconds and record it")
      ->type_name("S")
      ->check(CLI::PositiveNumber);
  submit.add_option("--maris", o.executable, "maris-cli on the nodes (default: this one)")->type_name("PATH");
  submit.add_flag("--resume", o.resume, "keep the complete cases of DIR; the tasks run the others");
  submit.add_flag("--force", o.force, "remove an earlier study in DIR and start over");
  submit.add_flag("--case-plots", o.case_plots, "each case writes its PNG plots too");
  submit.add_flag("--allow-large", o.allow_large, "cases may run beyond the work and memory limits");
  submit.add_flag("--no-plots", o.no_plots, "the collect job writes no PNG plots");
  submit.add_flag("--dry-run", o.dry_run, "write the case files and scripts, submit nothing");
}

int cmdSubmit(const StudyOptions& o) {
  PreparedStudy prepared = prepareStudy(o, o.out_dir, "maris-cli study submit");
  const StudyFolder& folder = prepared.folder;
  const StudyManifest manifest = readManifest(folder);
  const std::filesystem::path slurm = folder.root / "slurm";
  std::filesystem::create_directories(slurm / "logs");
  const std::string maris = o.executable.empty() ? std::filesystem::read_symlink("/proc/self/exe").string()
                                                 : std::filesystem::absolute(o.executable).string();
  const std::size_t cases = manifest.ids.size(), per_task = o.cases_per_task;
  const std::size_t tasks = (cases + per_task - 1) / per_task;
  const std::string dir = shellQuoted(folder.root.string());

  std::string array = "0-" + std::to_string(tasks - 1);
  if (o.max_parallel) array += "%" + std::to_string(o.max_parallel);
  std::string run_flags;
  if (o.timeout_s > 0) run_flags += " --timeout " + formatText("%.17g", o.timeout_s);
  if (o.case_plots) run_flags += " --case-plots";
  if (o.allow_large) run_flags += " --allow-large";
  const std::string cases_script =
      "#!/bin/bash\n"
      "# Maris study " + prepared.name + ": " + std::to_string(cases) + " cases, " + std::to_string(per_task) +
      " per array task (written by maris-cli study submit).\n"
      "#SBATCH --job-name=" + jobName(prepared.name) + "\n"
      "#SBATCH --array=" + array + "\n"
      "#SBATCH --cpus-per-task=" + std::to_string(o.cpus_per_task) + "\n" +
      commonDirectives(o) +
      "#SBATCH --output=" + (slurm / "logs" / "cases-%A_%a.out").string() + "\n"
      "set -eu\n"
      "first=$(( SLURM_ARRAY_TASK_ID * " + std::to_string(per_task) + " + 1 ))\n"
      "exec " + shellQuoted(maris) + " study run-cases " + dir + " --first \"$first\" --count " +
      std::to_string(per_task) + " --jobs \"${SLURM_CPUS_PER_TASK:-1}\"" + run_flags + "\n";
  const std::string collect_script =
      "#!/bin/bash\n"
      "# Collects the Maris study " + prepared.name + " after its job array, however its tasks ended.\n"
      "#SBATCH --job-name=" + jobName(prepared.name) + "-collect\n"
      "#SBATCH --cpus-per-task=1\n" +
      commonDirectives(o) +
      "#SBATCH --output=" + (slurm / "logs" / "collect-%j.out").string() + "\n"
      "set -eu\n"
      "exec " + shellQuoted(maris) + " study collect " + dir + (o.no_plots ? " --no-plots" : "") + "\n";
  writeFileAtomic(slurm / "cases.sbatch", cases_script);
  writeFileAtomic(slurm / "collect.sbatch", collect_script);
  std::printf("%zu cases in %zu array tasks: %s\n", cases, tasks, (slurm / "cases.sbatch").c_str());
  if (o.dry_run) {
    std::printf("dry run: nothing submitted; submit with\n  cd %s && jobid=$(sbatch --parsable cases.sbatch) && "
                "sbatch --dependency=afterany:${jobid%%%%;*} collect.sbatch\n", shellQuoted(slurm.string()).c_str());
    return kExitOk;
  }
  const CommandResult array_job = runCommand({"sbatch", "--parsable", (slurm / "cases.sbatch").string()}, slurm);
  const std::string array_id = array_job.out.substr(0, array_job.out.find_first_of(";\n"));
  if (array_job.exit_code != 0 || array_id.empty()) {
    std::fprintf(stderr, "maris-cli study submit: sbatch refused the job array (exit code %d): %s\n",
                 array_job.exit_code, array_job.err.c_str());
    return kExitUsage;
  }
  const CommandResult collect_job = runCommand(
      {"sbatch", "--parsable", "--dependency=afterany:" + array_id, (slurm / "collect.sbatch").string()}, slurm);
  const std::string collect_id = collect_job.out.substr(0, collect_job.out.find_first_of(";\n"));
  Json jobs = {{"array_job", array_id}, {"tasks", tasks}, {"cases_per_task", per_task}};
  if (collect_job.exit_code == 0 && !collect_id.empty()) jobs["collect_job"] = collect_id;
  writeFileAtomic(slurm / "jobs.json", jobs.dump(2) + "\n");
  std::printf("submitted job array %s (%zu tasks)\n", array_id.c_str(), tasks);
  if (!jobs.contains("collect_job")) {
    std::fprintf(stderr, "maris-cli study submit: sbatch refused the collect job (exit code %d): %s; run "
                         "`maris-cli study collect %s` when the array has ended\n",
                 collect_job.exit_code, collect_job.err.c_str(), folder.root.c_str());
    return kExitUsage;
  }
  std::printf("collect job %s runs after it: %s\n", collect_id.c_str(), folder.csv().c_str());
  return kExitOk;
}

}  // namespace maris::cli
