// maris-cli: the headless runner over the same engine as the GUI.
//   maris-cli list | show NAME | schema SCENE [--json] | run FILE|NAME [--set path=value ...] [--out DIR]
// Exit codes: 0 success, 1 usage/internal error or output folder refused, 2 invalid input (also a run beyond the
// work limits), 3 solver failure, 130 cancelled by SIGINT, 143 by SIGTERM.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/errors.hpp"
#include "core/input_limits.hpp"
#include "core/run_folder.hpp"
#include "core/run_output.hpp"
#include "catalog.hpp"
#include "plot_writer.hpp"

namespace {

using namespace maris;

enum ExitCode { kOk = 0, kUsage = 1, kInvalidInput = 2, kSolverFailure = 3 };

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

const char* kUsageText =
    "usage: maris-cli <command> [options]\n"
    "  list                         built-in scenarios (name, scene, description)\n"
    "  show NAME                    print a built-in scenario as JSON, ready to edit\n"
    "  schema SCENE [--json]        the parameter schema of a scene (names, units, defaults, ranges)\n"
    "  scenes                       the scenes compiled in\n"
    "  default                      the name of the default built-in scenario\n"
    "  run FILE|NAME [--set path=value ...] [--out DIR] [--force] [--allow-large] [--no-plots]\n"
    "                               run a scenario file or a built-in scenario; writes scenario.json,\n"
    "                               summary.json, one CSV per result table and PNG plots into DIR\n"
    "                               (default: maris-results/<name>) as a whole, or nothing;\n"
    "                               --force replaces an earlier run in DIR, --allow-large runs beyond\n"
    "                               the work limits\n"
    "exit codes: 0 success, 1 usage error or output folder refused, 2 invalid input or work limit,\n"
    "            3 solver failure, 130 cancelled (SIGINT), 143 cancelled (SIGTERM)\n";

// Indents every line after the first of a multi-line message by two spaces.
std::string indentLines(std::string text) {
  for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 3)) text.insert(at + 1, "  ");
  return text;
}

int cmdList() {
  std::printf("%-34s %-8s %s\n", "NAME", "SCENE", "DESCRIPTION");
  for (const auto& b : builtinScenarios()) {
    std::string line = b.scenario.name;
    std::printf("%-34s %-8s %s\n", b.id.c_str(), b.scenario.scene.c_str(), line.c_str());
  }
  return kOk;
}

int cmdScenes() {
  for (const auto& s : sceneCatalog()) std::printf("%-8s %s\n", s.name.c_str(), s.title.c_str());
  return kOk;
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
  return kOk;
}

int cmdSchema(const std::string& scene_name, bool as_json) {
  const auto& scene = requireScene(scene_name);
  if (as_json) {
    Json j{{"scene", scene.name}, {"title", scene.title}, {"description", scene.description},
           {"fields", schemaToJson(scene.schema)}};
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << scene.name << ": " << scene.title << "\n" << scene.description << "\n"
              << describeSchema(scene.schema);
  }
  return kOk;
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

int cmdRun(const std::vector<std::string>& args, int argc, char** argv) {
  std::string target, out_dir;
  std::vector<std::string> overrides;
  bool plots = true, force = false, allow_large = false, out_given = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const auto& a = args[i];
    if (a == "--set" && i + 1 < args.size()) overrides.push_back(args[++i]);
    else if (a == "--out" && i + 1 < args.size()) out_dir = args[++i], out_given = true;
    else if (a == "--no-plots") plots = false;
    else if (a == "--force") force = true;
    else if (a == "--allow-large") allow_large = true;
    else if (!a.empty() && a[0] == '-') throw InputError(a, "", "is not an option of `run`\n" + std::string(kUsageText));
    else if (target.empty()) target = a;
    else throw InputError(a, "", "unexpected extra argument");
  }
  if (target.empty()) throw InputError("run", "", "needs a scenario file or a built-in scenario name");
  if (out_given && out_dir.empty()) throw std::runtime_error("--out needs a folder name (it was empty)");

  Scenario scenario;
  std::string id;
  if (std::filesystem::exists(std::filesystem::symlink_status(target))) {  // a link loop is reported by the loader
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
  for (const auto& o : overrides) applyOverride(scenario, o);
  if (out_dir.empty()) out_dir = "maris-results/" + id;

  // Everything that can refuse the run does so before the solve: work limits, then the output folder.
  const WorkEstimate estimate = estimateWork(scene, scenario.parameters);
  if (auto errors = workLimitErrors(estimate); !allow_large && !errors.empty()) throw InputError(errors);
  installSignalHandlers();
  RunFolder folder(out_dir, {force, static_cast<std::uintmax_t>(estimate.output_bytes)});
  RunContext context(makeProgressPrinter(), &g_cancel);
  std::fprintf(stderr, "running %s (%s)\n", id.c_str(), scene.title.c_str());
  Results results = runScenario(scene, scenario, context);
  throwIfCancelled();
  for (const auto& w : results.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

  // A signal while writing cancels too: the staged folder is removed, the target left as it was.
  writeRunFolder(folder.staging(), scenario, results);
  if (plots) writePlotPngs(folder.staging(), results, argc, argv);
  throwIfCancelled();
  folder.commit();
  for (const auto& s : results.scalars)
    std::printf("%-28s %14.6g %-8s %s\n", s.name.c_str(), s.value, s.unit.c_str(), s.description.c_str());
  std::printf("wall time %.3f s, %ld steps (%ld rejected)\n", results.stats.wall_time_s, results.stats.steps,
              results.stats.rejected_steps);
  std::printf("results written to %s\n", folder.target().c_str());
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kUsageText, args.empty() ? stderr : stdout);
    return args.empty() ? kUsage : kOk;
  }
  const std::string cmd = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (cmd == "list") return cmdList();
    if (cmd == "scenes") return cmdScenes();
    if (cmd == "default") {
      std::printf("%s\n", defaultBuiltin().id.c_str());
      return kOk;
    }
    if (cmd == "show" && rest.size() == 1) return cmdShow(rest[0]);
    if (cmd == "schema" && !rest.empty())
      return cmdSchema(rest[0], rest.size() > 1 && rest[1] == "--json");
    if (cmd == "run") return cmdRun(rest, argc, argv);
    std::fputs(kUsageText, stderr);
    return kUsage;
  } catch (const InputError& e) {
    std::fprintf(stderr, "invalid input:\n  %s\n", indentLines(describeErrors(e.errors())).c_str());
    return kInvalidInput;
  } catch (const SolverError& e) {
    std::fprintf(stderr, "\nsolver failure: %s\n", e.what());
    return kSolverFailure;
  } catch (const RunCancelled&) {
    std::fprintf(stderr, "\ncancelled; nothing was written for this run\n");
    return 128 + g_signal.load();
  } catch (const Json::exception& e) {
    // The loaders turn JSON problems into InputErrors; one that escapes is still a problem of the input.
    std::fprintf(stderr, "invalid input:\n  %s\n", echoText(e.what(), 4 * kEchoLimit).c_str());
    return kInvalidInput;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "invalid input:\n  %s: %s\n", echoText(e.path1().string()).c_str(), e.code().message().c_str());
    return kInvalidInput;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "\nsolver failure: out of memory (the scenario asks for more memory than is available; "
                         "use fewer steps, samples or cells)\n");
    return kSolverFailure;
  } catch (const std::length_error& e) {
    std::fprintf(stderr, "\nsolver failure: a table would exceed the largest possible size (%s); use fewer steps, "
                         "samples or cells\n", e.what());
    return kSolverFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kUsage;
  }
}
