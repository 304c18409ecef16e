#include "cli_study.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "catalog.hpp"
#include "cli_conventions.hpp"
#include "cli_study_internal.hpp"
#include "core/input_limits.hpp"
#include "core/resources.hpp"
#include "core/run_output.hpp"
#include "plot_writer.hpp"
#include "study/study_collect.hpp"
#include "study_runner.hpp"

namespace maris::cli {

namespace {

using namespace maris::study;

// validate: each file as a study (its "format" says so) or a scenario, every problem listed.
int cmdValidate(const StudyOptions& options) {
  int exit_code = kExitOk;
  for (const auto& file : options.files) {
    try {
      const Json document =
          parseJsonLimited(readInputFile(file, file, InputLimits::kScenarioFileBytes), file);
      const auto folder = std::filesystem::absolute(file).parent_path();
      if (isStudyDocument(document)) {
        const Study study = studyFromJson(document, folder);
        const auto cases = expandStudy(study);
        if (auto errors = caseErrors(study, cases, options.allow_large); !errors.empty()) throw InputError(errors);
        std::printf("%s: valid study, %zu cases of scene %s (%s)\n", file.c_str(), cases.size(),
                    study.base.scene.c_str(), toString(study.kind));
      } else {
        Scenario scenario = scenarioFromJson(document);
        const auto& scene = requireScene(scenario.scene);
        upgradeParameters(scene, scenario.parameters);
        resolveDataPaths(scene.schema, scenario.parameters, folder);
        auto errors = validateParameters(scene, scenario.parameters);
        if (errors.empty() && !options.allow_large) errors = workLimitErrors(estimateWork(scene, scenario.parameters));
        if (!errors.empty()) throw InputError(errors);
        std::printf("%s: valid scenario of scene %s\n", file.c_str(), scene.name.c_str());
      }
    } catch (const InputError& e) {
      std::fprintf(stderr, "%s: invalid:\n  %s\n", file.c_str(), indentLines(describeErrors(e.errors())).c_str());
      exit_code = kExitInvalidInput;
    }
  }
  return exit_code;
}

std::string defaultOut(const std::string& study_file) {
  return "maris-results/" + std::filesystem::path(study_file).stem().string();
}

int cmdRun(const StudyOptions& options, int argc, char** argv) {
  const std::string out = options.out_dir.empty() ? defaultOut(options.study_file) : options.out_dir;
  if (!options.no_plots || options.case_plots) requirePlotRenderer();  // before any case runs
  PreparedStudy prepared = prepareStudy(options, out, "maris-cli study run");
  const StudyFolder& folder = prepared.folder;
  StudyManifest manifest = readManifest(folder);
  CaseRunOptions run;
  run.jobs = options.jobs ? options.jobs : availableProcessors();
  run.timeout_s = options.timeout_s;
  run.case_plots = options.case_plots;
  run.allow_large = options.allow_large;
  std::fprintf(stderr, "study %s: %zu cases of scene %s, %u at once, into %s\n", prepared.name.c_str(),
               manifest.ids.size(), manifest.scene.c_str(), run.jobs, folder.root.c_str());
  const auto started_at = std::chrono::system_clock::now();
  const CaseRunTally tally = runCases(folder, manifest.ids, run);
  manifest.json["runs"].push_back({{"started_at", isoUtc(started_at)},
                                   {"wall_s", tally.wall_s},
                                   {"jobs", run.jobs},
                                   {"host_threads", availableProcessors()},
                                   {"cases_run", tally.ok + tally.failed + tally.timeout},
                                   {"skipped_complete", tally.skipped},
                                   {"ok", tally.ok},
                                   {"failed", tally.failed},
                                   {"timeout", tally.timeout},
                                   {"cancelled", tally.cancel_signal != 0}});
  const int collected = collectAndReport(folder, manifest, options.no_plots || tally.cancel_signal != 0, argc, argv);
  if (tally.cancel_signal != 0) {
    std::fprintf(stderr, "cancelled; complete cases are kept: `maris-cli study run %s --out %s --resume` finishes "
                         "the study\n", options.study_file.c_str(), out.c_str());
    return tally.cancel_signal == SIGTERM ? kExitTerminated : kExitInterrupted;
  }
  return collected;
}

// What one Slurm array task runs: the prepared cases [first, first + count) of DIR that are not complete.
int cmdRunCases(const StudyOptions& options) {
  const StudyFolder folder{std::filesystem::absolute(options.out_dir).lexically_normal()};
  const StudyManifest manifest = readManifest(folder);
  if (options.first < 1 || options.first > manifest.ids.size())
    throw InputError("--first", std::to_string(options.first),
                     "must be a case number in [1, " + std::to_string(manifest.ids.size()) + "]");
  const std::size_t end = std::min(manifest.ids.size(), options.first - 1 + std::max<std::size_t>(options.count, 1));
  const std::vector<std::string> ids(manifest.ids.begin() + static_cast<long>(options.first - 1),
                                     manifest.ids.begin() + static_cast<long>(end));
  CaseRunOptions run;
  run.jobs = options.jobs ? options.jobs : availableProcessors();
  run.timeout_s = options.timeout_s;
  run.case_plots = options.case_plots;
  run.allow_large = options.allow_large;
  const CaseRunTally tally = runCases(folder, ids, run);
  std::printf("cases %s-%s: %zu ok, %zu failed, %zu timed out, %zu complete before\n", ids.front().c_str(),
              ids.back().c_str(), tally.ok, tally.failed, tally.timeout, tally.skipped);
  if (tally.cancel_signal != 0) return tally.cancel_signal == SIGTERM ? kExitTerminated : kExitInterrupted;
  return tally.failed + tally.timeout > 0 ? kExitSolverFailure : kExitOk;
}

int cmdCollect(const StudyOptions& options, int argc, char** argv) {
  const StudyFolder folder{std::filesystem::absolute(options.out_dir).lexically_normal()};
  if (!options.no_plots) requirePlotRenderer();
  FolderLock lock(folder.root, "maris-cli study collect");
  StudyManifest manifest = readManifest(folder);
  removeOldVersionLeftovers(folder);
  return collectAndReport(folder, manifest, options.no_plots, argc, argv);
}

void addRunOptions(CLI::App& command, StudyOptions& o) {
  command.add_option("--jobs", o.jobs, "cases at once (default: every processor available)")
      ->type_name("N")
      ->check(CLI::Range(1u, 4096u));
  command.add_option("--timeout", o.timeout_s, "stop a case after this many seconds and record it (default: none)")
      ->type_name("S")
      ->check(CLI::PositiveNumber);
  command.add_flag("--case-plots", o.case_plots, "each case writes its PNG plots too (slower)");
  command.add_flag("--allow-large", o.allow_large, "cases may run beyond the work and memory limits");
}

}  // namespace

void StudyCommands::add(CLI::App& app) {
  StudyOptions& o = options;
  validate = app.add_subcommand("validate", "check scenario or study files without running them");
  validate->add_option("FILE", o.files, "scenario (*.json) or study files")->required()->type_name("");
  validate->add_flag("--allow-large", o.allow_large, "do not count the work limits as problems");

  study = app.add_subcommand("study", "design studies: many runs of one scene (grid, table, Latin hypercube)");
  study->require_subcommand(1);
  run = study->add_subcommand("run", "run every case of a study, write study.csv, study.json and plots");
  run->add_option("STUDY", o.study_file, "a study file (see `maris-cli schema study`)")->required()->type_name("");
  run->add_option("--out", o.out_dir, "the study's folder (default: maris-results/STUDY)")->type_name("DIR");
  addRunOptions(*run, o);
  run->add_flag("--resume", o.resume, "keep the complete cases of DIR and run the others");
  run->add_flag("--force", o.force, "remove an earlier study in DIR and start over");
  run->add_flag("--no-plots", o.no_plots, "write no PNG plots of the study");

  run_cases = study->add_subcommand("run-cases", "run prepared cases of a study folder (a Slurm array task)");
  run_cases->add_option("DIR", o.out_dir, "a study folder written by `study run` or `study submit`")
      ->required()
      ->type_name("");
  run_cases->add_option("--first", o.first, "the first case's number (1-based)")->type_name("K")->required();
  run_cases->add_option("--count", o.count, "how many cases from K")->type_name("C")->required()->check(CLI::PositiveNumber);
  addRunOptions(*run_cases, o);

  collect = study->add_subcommand("collect", "write study.csv, study.json and plots from the complete cases");
  collect->add_option("DIR", o.out_dir, "a study folder")->required()->type_name("");
  collect->add_flag("--no-plots", o.no_plots, "write no PNG plots");

  submit = study->add_subcommand("submit", "write the case files and an sbatch job array into DIR and submit it");
  addSubmitOptions(*submit, o);
  const std::string codes =
      "Exit codes:\n"
      "  0    every case succeeded (submit: the jobs were submitted)\n"
      "  1    usage error, or an output folder refused (another study in it, a changed study with --resume)\n"
      "  2    invalid study: every bad case is named, nothing was run\n"
      "  3    some case failed, timed out or was not run (the others are complete)\n"
      "  130  cancelled by SIGINT (Ctrl-C); complete cases are kept, --resume finishes the study\n"
      "  143  cancelled by SIGTERM; the same\n";
  for (CLI::App* command : {study, run, run_cases, collect, submit}) command->footer(codes);
}

std::optional<int> StudyCommands::dispatch(int argc, char** argv) {
  const char* command = nullptr;
  try {
    if (validate->parsed()) return cmdValidate(options);
    if (!study->parsed()) return std::nullopt;
    if (run->parsed()) command = "maris-cli study run";
    if (run_cases->parsed()) command = "maris-cli study run-cases";
    if (collect->parsed()) command = "maris-cli study collect";
    if (submit->parsed()) command = "maris-cli study submit";
    if (run->parsed()) return cmdRun(options, argc, argv);
    if (run_cases->parsed()) return cmdRunCases(options);
    if (collect->parsed()) return cmdCollect(options, argc, argv);
    if (submit->parsed()) return cmdSubmit(options);
  } catch (const study::StudyFolderError& e) {
    std::fputs(usageErrorText(command ? command : "maris-cli study", e.what()).c_str(), stderr);
    return kExitUsage;
  } catch (const StudyFolderRefused& e) {
    std::fputs(usageErrorText(command ? command : "maris-cli study", e.what()).c_str(), stderr);
    return kExitUsage;
  }
  return kExitUsage;
}

}  // namespace maris::cli
