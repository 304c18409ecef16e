// Study throughput: how many cases per second `maris-cli study run` gets through with --jobs 1 and 2, and
// what the per-case process costs (start, reading, writing) beside the solve; and, for a study of 10 000
// trivial cases, the time to expand and check every case, to write the case files, to run them and to
// collect study.csv. Wall times of a shared machine: run it on a quiet one.
//   bench_study_throughput [--cases 200] [--medium 40] [--trivial 10000] [--no-trivial-run] [--maris PATH]
//                          [--dir DIR]
// small: riser cantilever statics (ms of solve); medium: the same with 1 s of dynamics (about 0.1 s of solve).
// A count of 0 leaves that part out. --dir on a tmpfs (/dev/shm/x) takes the device's flushes out of the
// times. Prints one line per measurement (name, value, unit).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/input_limits.hpp"
#include "study/study.hpp"
#include "study/study_collect.hpp"
#include "study/study_folder.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using maris::Json;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void report(const char* name, double value, const char* unit) { std::printf("%-44s %12.4g %s\n", name, value, unit); }

// Runs maris-cli with `args` (its output to /dev/null); returns the exit code.
int runMaris(const std::string& maris, std::vector<std::string> args) {
  args.insert(args.begin(), maris);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, "/dev/null", 01, 0);
  posix_spawn_file_actions_addopen(&files, 2, "/dev/null", 01, 0);
  pid_t pid = 0;
  if (::posix_spawn(&pid, maris.c_str(), &files, nullptr, argv.data(), environ) != 0) return -1;
  posix_spawn_file_actions_destroy(&files);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

Json readJson(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return Json::parse(s.str());
}

// A riser cantilever under a tip load at `count` lengths: statics only (a few ms of solve), or with
// `end_time` seconds of dynamics after it (about 0.1 s of solve per simulated second).
std::string cantileverStudy(std::size_t count, double end_time = 0.0) {
  // A {from, to, count} range needs two values or more: one case is a list of one.
  const std::string lengths = count == 1 ? "[10]" : R"({"from": 10, "to": 30, "count": )" + std::to_string(count) + "}";
  return R"({"format": "maris-study/1", "name": "throughput", "base": "riser_cantilever_tip_load",
    "set": {"solver.end_time": )" + std::to_string(end_time) + R"(},
    "grid": {"geometry.length": )" + lengths + "}}";
}

// Per-case costs from a run study: the case processes' wall time and the solves' own wall time.
void caseCosts(const fs::path& out, const char* label) {
  const Json manifest = readJson(out / "study.json");
  double process = 0.0, solve = 0.0;
  for (const auto& c : manifest["collected"]["cases"]) {
    process += c.value("wall_s", 0.0);
    solve += readJson(out / "cases" / c["id"].get<std::string>() / "summary.json")["solver"]["wall_time"].value("value", 0.0);
  }
  const double n = static_cast<double>(manifest["collected"]["cases"].size());
  std::string name = std::string(label) + ": case process wall, mean";
  report(name.c_str(), 1e3 * process / n, "ms");
  name = std::string(label) + ": solve wall in it, mean";
  report(name.c_str(), 1e3 * solve / n, "ms");
  name = std::string(label) + ": overhead share (start, read, write)";
  report(name.c_str(), 100.0 * (1.0 - solve / process), "%");
}

// Runs `study` with --jobs 1 and 2; reports wall, throughput, per-case costs and the speed-up.
bool measureJobs(const std::string& maris, const fs::path& dir, const std::string& name, const std::string& study,
                 std::size_t cases) {
  { std::ofstream(dir / (name + ".json")) << study; }
  double wall[3] = {0, 0, 0};
  for (int jobs : {1, 2}) {
    const fs::path out = dir / (name + std::to_string(jobs));
    const auto t0 = Clock::now();
    const int code = runMaris(maris, {"study", "run", (dir / (name + ".json")).string(), "--out", out.string(),
                                      "--jobs", std::to_string(jobs), "--no-plots"});
    wall[jobs] = since(t0);
    if (code != 0) {
      std::fprintf(stderr, "%s: study run --jobs %d failed (exit code %d)\n", name.c_str(), jobs, code);
      return false;
    }
    const std::string label = std::to_string(cases) + " " + name + " cases, --jobs " + std::to_string(jobs);
    report((label + ": wall").c_str(), wall[jobs], "s");
    report((label + ": throughput").c_str(), static_cast<double>(cases) / wall[jobs], "cases/s");
    caseCosts(out, label.c_str());
  }
  report((name + ": speed-up of --jobs 2 over --jobs 1").c_str(), wall[1] / wall[2], "");
  return true;
}

// 10 000 trivial cases: the same cantilever, so each case is one short process. Returns false on a failure.
bool measureTrivial(const std::string& maris, const fs::path& dir, std::size_t trivial, bool trivial_run) {
  { std::ofstream(dir / "trivial.json") << cantileverStudy(trivial); }
  auto t0 = Clock::now();
  const maris::study::Study study = maris::study::loadStudyFile(dir / "trivial.json");
  const auto expanded = maris::study::expandStudy(study);
  report("trivial: read and expand", since(t0), "s");
  t0 = Clock::now();
  const auto errors = maris::study::caseErrors(study, expanded, false);
  report("trivial: check every case", since(t0), "s");
  if (!errors.empty()) {
    std::fprintf(stderr, "%s\n", maris::describeErrors(errors).c_str());
    return false;
  }
  const maris::study::StudyFolder folder{dir / "trivial"};
  t0 = Clock::now();
  maris::study::prepareStudyFolder(folder, study, expanded, dir / "trivial.json", false);
  report("trivial: write case files and study.json", since(t0), "s");
  if (!trivial_run) return true;
  t0 = Clock::now();
  const int code = runMaris(maris, {"study", "run", (dir / "trivial.json").string(), "--out", folder.root.string(),
                                    "--jobs", "2", "--no-plots", "--resume"});
  const double run_wall = since(t0);
  report("trivial: study run --jobs 2 (all cases)", run_wall, "s");
  report("trivial: throughput", static_cast<double>(trivial) / run_wall, "cases/s");
  if (code != 0) std::fprintf(stderr, "trivial study run: exit code %d\n", code);
  t0 = Clock::now();
  maris::study::StudyManifest manifest = maris::study::readManifest(folder);
  const auto collected = maris::study::collectStudy(folder, manifest);
  report("trivial: collect (read every summary.json)", since(t0), "s");
  t0 = Clock::now();
  maris::study::writeCollected(folder, manifest, collected);
  report("trivial: write study.csv and study.json", since(t0), "s");
  report("trivial: study.csv size", static_cast<double>(fs::file_size(folder.csv())) / 1e6, "MB");
  return code == 0;
}

int run(int argc, char** argv) {
  std::size_t cases = 200, medium = 40, trivial = 10000;
  bool trivial_run = true;
  std::string maris = MARIS_CLI_PATH;
  fs::path dir = fs::temp_directory_path() / ("maris_bench_study_" + std::to_string(::getpid()));
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cases" && i + 1 < argc) cases = std::strtoul(argv[++i], nullptr, 10);
    else if (a == "--medium" && i + 1 < argc) medium = std::strtoul(argv[++i], nullptr, 10);
    else if (a == "--trivial" && i + 1 < argc) trivial = std::strtoul(argv[++i], nullptr, 10);
    else if (a == "--no-trivial-run") trivial_run = false;
    else if (a == "--maris" && i + 1 < argc) maris = argv[++i];
    else if (a == "--dir" && i + 1 < argc) dir = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--cases N] [--medium N] [--trivial N] [--no-trivial-run] [--maris PATH] [--dir DIR]\n", argv[0]);
      return 1;
    }
  }
  std::error_code error;
  if (fs::exists(dir, error) && !fs::is_empty(dir, error)) {  // it is removed at the end: never someone's files
    std::fprintf(stderr, "--dir %s is not empty: name a new or empty folder\n", dir.c_str());
    return 1;
  }
  fs::create_directories(dir);
  bool ok = cases == 0 || measureJobs(maris, dir, "small", cantileverStudy(cases), cases);
  ok = ok && (medium == 0 || measureJobs(maris, dir, "medium", cantileverStudy(medium, 1.0), medium));
  ok = ok && (trivial == 0 || measureTrivial(maris, dir, trivial, trivial_run));
  fs::remove_all(dir);
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each measurement shows at once, also into a pipe
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_study_throughput: %s\n", e.what());
    return 1;
  }
}
