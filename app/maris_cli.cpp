// maris-cli: the headless runner over the same engine as the GUI.
//   maris-cli list | show NAME | schema SCENE|study [--json] | scenes | default
//           | run FILE|NAME [--set path=value ...] [--out DIR] [--force] [--allow-large] [--no-plots] [--no-sync]
//           | validate FILE... | study run|run-cases|collect|submit ...   (cli_study.hpp)
// Options are parsed with CLI11 under the conventions shared with `maris` (cli_conventions.hpp):
// --help, --version, usage errors with exit code 1; the other exit codes are listed there.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "cli_conventions.hpp"
#include "cli_study.hpp"
#include "cli_study_internal.hpp"
#include "core/errors.hpp"
#include "core/input_limits.hpp"
#include "core/resources.hpp"
#include "core/run_folder.hpp"
#include "core/run_output.hpp"
#include "catalog.hpp"
#include "plot_writer.hpp"
#include "study/study_schema.hpp"

namespace {

using namespace maris;
using namespace maris::cli;

std::atomic<bool> g_cancel{false};
std::atomic<int> g_signal{SIGINT};

extern "C" void onCancelSignal(int signal) {
  g_signal.store(signal);
  g_cancel.store(true);
}

// SIGINT and SIGTERM cancel the run (exit 128 + signal); a file-size limit becomes a write error, not a crash.
void installSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = onCancelSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::signal(SIGXFSZ, SIG_IGN);
}

void throwIfCancelled() {
  if (g_cancel.load()) throw RunCancelled();
}


// What `run` was asked to do.
struct RunOptions {
  std::string target;                  // a scenario file or a built-in scenario's name
  std::vector<std::string> overrides;  // --set path=value, in the order given
  std::string out_dir;                 // --out ("" = maris-results/<name>)
  bool out_given = false;              // --out was on the command line (an empty DIR is then a usage error)
  bool no_plots = false;               // --no-plots
  bool force = false;                  // --force: replace an earlier run in DIR
  bool allow_large = false;            // --allow-large: run beyond the work limits
  bool no_sync = false;                // --no-sync: do not wait for the device (a study syncs its cases in batches)
  bool study_case = false;             // --study-case: a study's case; the study removes old versions' leftovers
};

int cmdList() {
  std::printf("%-34s %-8s %s\n", "NAME", "SCENE", "DESCRIPTION");
  for (const auto& b : builtinScenarios()) {
    std::string line = b.scenario.name;
    std::printf("%-34s %-8s %s\n", b.id.c_str(), b.scenario.scene.c_str(), line.c_str());
  }
  return kExitOk;
}

int cmdScenes() {
  for (const auto& s : sceneCatalog()) std::printf("%-8s %s\n", s.name.c_str(), s.title.c_str());
  return kExitOk;
}

const BuiltinScenario& requireBuiltin(const std::string& id) {
  if (const auto* b = findBuiltin(id)) return *b;
  std::vector<std::string> ids;
  for (const auto& b : builtinScenarios()) ids.push_back(b.id);
  const auto guess = didYouMean(id, ids);
  throw InputError("NAME", "\"" + id + "\"",
                   "is neither a file nor a built-in scenario (see `maris-cli list`)" +
                       (guess.empty() ? std::string() : "; did you mean '" + guess + "'?"));
}

int cmdShow(const std::string& id) {
  std::cout << scenarioToText(requireBuiltin(id).scenario);
  return kExitOk;
}

int cmdSchema(const std::string& scene_name, bool as_json) {
  if (scene_name == "study" && !findScene(scene_name)) {  // the study file format
    std::cout << (as_json ? study::studySchemaJson().dump(2) + "\n" : study::describeStudySchema());
    return kExitOk;
  }
  const auto& scene = requireScene(scene_name);
  if (as_json) {
    Json j{{"scene", scene.name}, {"title", scene.title}, {"description", scene.description},
           {"fields", schemaToJson(scene.schema)}};
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << scene.name << ": " << scene.title << "\n" << scene.description << "\n"
              << describeSchema(scene.schema);
  }
  return kExitOk;
}

// Progress on stderr: a redrawn bar on a terminal, plain lines otherwise (logs, CI).
RunContext::ProgressFn makeProgressPrinter() {
  const bool tty = ::isatty(STDERR_FILENO);
  auto last_percent = std::make_shared<int>(-1);
  return [tty, last_percent](double fraction, const std::string& stage) {
    const int percent = static_cast<int>(fraction * 100.0 + 0.5);
    if (tty) {
      const int width = 30, filled = percent * width / 100;
      std::fprintf(stderr, "\r[%.*s%*s] %3d%% %-30.30s", filled, "##############################",
                   width - filled, "", percent, stage.c_str());
      if (percent >= 100) std::fputc('\n', stderr);
      std::fflush(stderr);
    } else if (percent / 10 != *last_percent / 10 || percent == 100) {
      std::fprintf(stderr, "progress %3d%% %s\n", percent, stage.c_str());
    }
    *last_percent = percent;
  };
}

int cmdRun(const RunOptions& options, int argc, char** argv) {
  const std::string& target = options.target;
  std::string out_dir = options.out_dir;
  if (options.out_given && out_dir.empty()) {
    std::fprintf(stderr, "%s\n", usageErrorText("maris-cli run", "--out needs a folder name (it was empty)").c_str());
    return kExitUsage;
  }

  Scenario scenario;
  std::string id;
  const bool from_file = std::filesystem::exists(std::filesystem::symlink_status(target));
  if (from_file) {  // a link loop is reported by the loader
    scenario = loadScenarioFile(target);
    id = std::filesystem::path(target).stem().string();
  } else {
    const auto& b = requireBuiltin(target);
    scenario = b.scenario;
    id = b.id;
  }
  const auto& scene = requireScene(scenario.scene);
  // Old field names first, so --set and the saved scenario.json use the current schema.
  for (const auto& note : upgradeParameters(scene, scenario.parameters))
    std::fprintf(stderr, "note: %s\n", note.c_str());
  // The file's data paths are relative to its folder (scenario.json in DIR then names them absolutely);
  // --set values are relative to the current folder, as anything typed in a shell.
  if (from_file)
    resolveDataPaths(scene.schema, scenario.parameters, std::filesystem::absolute(target).parent_path());
  for (const auto& o : options.overrides) applyOverride(scenario, o);
  resolveDataPaths(scene.schema, scenario.parameters, std::filesystem::current_path());  // those given by --set
  if (out_dir.empty()) out_dir = "maris-results/" + id;

  // Everything that can refuse the run does so before the solve: work limits, then the output folder.
  const WorkEstimate estimate = estimateWork(scene, scenario.parameters);
  if (auto errors = workLimitErrors(estimate); !options.allow_large && !errors.empty()) throw InputError(errors);
  if (!options.no_plots) requirePlotRenderer();  // a missing renderer refuses before the solve
  installSignalHandlers();
  RunFolder folder(out_dir, {.replace = options.force,
                             .expected_bytes = static_cast<std::uintmax_t>(estimate.output_bytes),
                             .sync = !options.no_sync,
                             .remove_old_version_leftovers = !options.study_case});
  RunContext context(makeProgressPrinter(), &g_cancel);
  context.setViewWanted(false);  // a run folder holds no 3D view
  std::fprintf(stderr, "running %s (%s)\n", id.c_str(), scene.title.c_str());
  const auto started_at = std::chrono::system_clock::now();
  Results results = runScenario(scene, scenario, context);
  throwIfCancelled();
  for (const auto& w : results.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

  // A signal while writing cancels too: the staged folder is removed, the target left as it was.
  writeRunFolder(folder.staging(), scenario, results, started_at);
  if (!options.no_plots) writePlotPngs(folder.staging(), results, argc, argv);
  throwIfCancelled();
  folder.commit();
  for (const auto& s : results.scalars)
    std::printf("%-28s %14.6g %-8s %s\n", s.name.c_str(), s.value, s.unit.c_str(), s.description.c_str());
  std::printf("wall time %.3f s, %ld steps (%ld rejected)\n", results.stats.wall_time_s, results.stats.steps,
              results.stats.rejected_steps);
  std::printf("results written to %s\n", folder.target().c_str());
  return kExitOk;
}

// The command line, as CLI11 reads it; `run` fills `run_options`.
struct Commands {
  CLI::App app{"Runs Maris scenarios without a display, over the same engine as the desktop application `maris`.\n",
               "maris-cli"};
  CLI::App* list = nullptr;
  CLI::App* show = nullptr;
  CLI::App* schema = nullptr;
  CLI::App* scenes = nullptr;
  CLI::App* default_scenario = nullptr;
  CLI::App* run = nullptr;
  std::string name;       // show NAME
  std::string scene;      // schema SCENE
  bool as_json = false;   // schema --json
  RunOptions run_options;
  StudyCommands study;  // validate, study run|run-cases|collect|submit

  Commands() {
    applyConventions(app, true);
    app.require_subcommand(1);
    list = app.add_subcommand("list", "built-in scenarios (name, scene, description)");
    show = app.add_subcommand("show", "print a built-in scenario as JSON, ready to edit");
    show->add_option("NAME", name, "a built-in scenario's name (see `maris-cli list`)")->required()->type_name("");
    schema = app.add_subcommand("schema", "the parameter schema of a scene (names, units, defaults, ranges), or of "
                                          "study files (`schema study`)");
    schema->add_option("SCENE", scene, "a scene's name (see `maris-cli scenes`), or study")->required()->type_name("");
    schema->add_flag("--json", as_json, "as JSON");
    scenes = app.add_subcommand("scenes", "the scenes compiled in");
    default_scenario = app.add_subcommand("default", "the name of the default built-in scenario");
    run = app.add_subcommand("run", "run a scenario; write scenario.json, summary.json, CSV tables and PNG plots");
    run->add_option("FILE|NAME", run_options.target, "a scenario file (*.json) or a built-in scenario's name")
        ->required()
        ->type_name("");
    run->add_option("--set", run_options.overrides, "set one parameter before the run (repeatable), e.g. --set x=2")
        ->type_name("PATH=VALUE")
        ->allow_extra_args(false);
    run->add_option("--out", run_options.out_dir, "the folder for the results (default: maris-results/NAME)")
        ->type_name("DIR");
    run->add_flag("--no-plots", run_options.no_plots, "write no PNG plots");
    run->add_flag("--force", run_options.force, "replace an earlier run's results in DIR (as a whole)");
    run->add_flag("--allow-large", run_options.allow_large, "run beyond the work and memory limits");
    run->add_flag("--no-sync", run_options.no_sync,
                  "do not wait until the results are on the disk (faster; a power loss soon after can leave "
                  "them empty): for a caller that syncs many runs at once, as `study run` does");
    // Not in --help: what `study run` passes to its cases (one listing of the cases folder per study, not
    // one per case).
    run->add_flag("--study-case", run_options.study_case, "")->group("");
    study.add(app);
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  // `maris-cli help [COMMAND]` is `maris-cli [COMMAND] --help`.
  if (!args.empty() && args[0] == "help") {
    args.erase(args.begin());
    args.push_back("--help");
  }
  Commands commands;
  const ParseOutcome outcome = parseArguments(commands.app, args);
  if (outcome.exit_code) return reportOutcome(outcome);
  try {
    if (commands.list->parsed()) return cmdList();
    if (commands.scenes->parsed()) return cmdScenes();
    if (commands.default_scenario->parsed()) {
      std::printf("%s\n", defaultBuiltin().id.c_str());
      return kExitOk;
    }
    if (commands.show->parsed()) return cmdShow(commands.name);
    if (commands.schema->parsed()) return cmdSchema(commands.scene, commands.as_json);
    if (const auto code = commands.study.dispatch(argc, argv)) return *code;
    if (commands.run->parsed()) {
      commands.run_options.out_given = commands.run->get_option("--out")->count() > 0;
      return cmdRun(commands.run_options, argc, argv);
    }
    return kExitUsage;  // not reached: parseArguments requires one command
  } catch (const InputError& e) {
    std::fprintf(stderr, "invalid input:\n  %s\n", indentLines(describeErrors(e.errors())).c_str());
    return kExitInvalidInput;
  } catch (const SolverError& e) {
    std::fprintf(stderr, "\nsolver failure: %s\n", e.what());
    return kExitSolverFailure;
  } catch (const RunCancelled&) {
    std::fprintf(stderr, "\ncancelled; nothing was written for this run\n");
    return g_signal.load() == SIGTERM ? kExitTerminated : kExitInterrupted;
  } catch (const Json::exception& e) {
    // The loaders turn JSON problems into InputErrors; one that escapes is still a problem of the input.
    std::fprintf(stderr, "invalid input:\n  %s\n", echoText(e.what(), 4 * kEchoLimit).c_str());
    return kExitInvalidInput;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "invalid input:\n  %s: %s\n", echoText(e.path1().string()).c_str(), e.code().message().c_str());
    return kExitInvalidInput;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "\nsolver failure: out of memory (the scenario asks for more memory than is available; "
                         "use fewer steps, samples or cells)\n");
    return kExitSolverFailure;
  } catch (const std::length_error& e) {
    std::fprintf(stderr, "\nsolver failure: a table would exceed the largest possible size (%s); use fewer steps, "
                         "samples or cells\n", e.what());
    return kExitSolverFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitUsage;
  }
}
