// maris-cli's study commands and `validate`:
//   validate FILE...                          scenarios or studies, nothing run
//   study run STUDY [--out DIR] [--jobs N] [--resume] [--force] [--timeout S] [--no-plots] [--case-plots]
//   study run-cases DIR --first K --count C   prepared cases of DIR (what each Slurm array task runs)
//   study collect DIR                         study.csv, study.json and plots from whatever is complete
//   study submit STUDY --out DIR --engine slurm [...]   case files, sbatch scripts, submission
// Exit codes: 0 every case succeeded; 1 usage error or output folder refused; 2 invalid study (every bad
// case named, nothing run); 3 some case failed or timed out (the others ran); 130/143 cancelled.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace maris::cli {

struct StudyOptions {
  std::vector<std::string> files;  // validate FILE...
  std::string study_file;          // study run/submit STUDY
  std::string out_dir;             // --out (run, submit) or DIR (run-cases, collect)
  unsigned jobs = 0;               // --jobs (0: every processor available)
  double timeout_s = 0.0;          // --timeout per case
  bool resume = false, force = false, no_plots = false, case_plots = false, allow_large = false;
  std::size_t first = 1, count = 0;  // run-cases --first K --count C
  // submit
  std::string engine, partition, time, mem, account, executable;
  unsigned max_parallel = 0, cases_per_task = 1, cpus_per_task = 1;
  bool dry_run = false;
};

struct StudyCommands {
  CLI::App* validate = nullptr;
  CLI::App* study = nullptr;
  CLI::App* run = nullptr;
  CLI::App* run_cases = nullptr;
  CLI::App* collect = nullptr;
  CLI::App* submit = nullptr;
  StudyOptions options;

  void add(CLI::App& app);
  // The exit code of the study command or `validate` that was parsed; nullopt if none was.
  std::optional<int> dispatch(int argc, char** argv);
};

}  // namespace maris::cli
