// Work–precision of the riser scene: CPU time against error for the four variants J2, J3,
// A2, A3 and the integrators core/ode.hpp offers (RK4 fixed step as the scene uses, DOPRI5 adaptive),
// on the paper's case 5 (riser_paper_case5_j3: 500 m riser, elliptical top motion, 1 m/s current,
// 36 s) and on a 3D cable case (built-in scenario riser_cable_3d_circle: a 30 m cable whose top whirls on a
// circle in a current, 10 s).
//   error_same_n:   max over outputs (every 0.2 s) of |r_mid - r_mid,ref| / max |r_mid,ref(t) - r_mid,ref(0)|,
//                   r_mid = the point at s = L/2, reference = the same n and variant integrated by the most
//                   accurate method within the budget (column `reference`: DOPRI5 rtol 1e-10, RK4 at 0.2 or
//                   0.45 x its limit, implicit at T/3200, tolerance 1e-7);
//   error_finest_n: the same against the J3 reference at the run's finest n (column finest_n).
//   note:           why a run failed (the solver's message: time, step, quantity) or was skipped (estimated CPU
//                   above the budget); its errors are then inf.
// Also the CPU time of one right-hand side evaluation against n (must grow linearly).
// Times are thread CPU times (the machine may be shared), integration only (statics excluded).
//   bench_riser_work_precision [out.csv] [n_max (default 400; 1000 adds an implicit J3 run at n = 1000)]
//                              [case5_end_time (default 36)] [cases: all | case5 | cable3d]
//                              [cable_n_max (default n_max; the cable's torsion limit makes n = 100 costly)]
// Environment: MARIS_BENCH_NLIST / MARIS_BENCH_CABLE_NLIST = comma lists of n to run (instead of n ≤ n_max);
// either one merges the rows into an existing out.csv (rows of the same case, variant, n, method and setting
// are replaced, the others kept; MARIS_BENCH_MERGE=0/1 overrides), MARIS_BENCH_ROW_BUDGET = CPU seconds above
// which a run (estimated from the measured right-hand-side cost) is skipped with a note (default 180),
// MARIS_BENCH_REFERENCE_BUDGET = the same for the choice of the same-n reference (default: the row budget),
// MARIS_BENCH_VARIANTS / MARIS_BENCH_METHODS = comma lists restricting (and ordering) variants and methods,
// MARIS_BENCH_ESTIMATE_ONLY=1 prints the estimates and runs nothing, MARIS_BENCH_SKIPPED_ONLY=1 writes only the
// rows skipped for their estimated cost (their notes), without integrating anything; MARIS_BENCH_RERUN_SKIPPED=1
// runs only the settings whose row in out.csv was skipped for its estimated cost or is absent (with a larger row
// budget: filling in the costly explicit rows at large n, and rows earlier restricted runs left out, without
// re-running the others); MARIS_BENCH_FINEST_N = n of the "finest n" reference when above the largest n run
// (rows at smaller n measured against the same finest n as the rest of the CSV, without re-running that n).
// Integrators: RK4 at 0.9, 0.45, 0.225 x its stability estimate, DOPRI5 rtol 1e-3/1e-6/1e-8, and the scene's
// implicit generalized-alpha (riser_integration) at T/25, T/50, T/100, T/200 of the top-motion period.
// Plot: bench/tools/work_precision_plot (built with the GUI) renders the CSV to PNG with the GUI's plot
// code, e.g. --x cpu_time --y error_same_n --series variant,method --where case=case5 --where n=100.
// Besides the CSV it writes OUT.md (OUT without ".csv"), from the whole (merged) CSV: markdown tables of the
// right-hand-side cost against n, case 5 at n = 100, RK4 and implicit against n, skipped and failed rows.
// scripts/bench_riser.sh runs the set the docs quote (build, bench, tables, PNGs).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/ode.hpp"
#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_integration.hpp"
#include "riser/riser_results.hpp"
#include "riser/riser_statics.hpp"
#include "bench_clock.hpp"
#include "tools/riser_work_precision_summary.hpp"
#include "tools/work_precision_rows.hpp"

using namespace maris;
using namespace maris::riser;

namespace {

RiserParameters builtin(const std::string& id) {
  const auto text = builtinResource("scenarios/riser/" + id + ".json");
  return riserBinder().read(scenarioFromText(std::string(*text)).parameters);
}

struct Variant {
  const char* name;
  const char* formulation;
  bool torsion;
};
constexpr Variant kVariants[] = {{"J2", "joint", false}, {"J3", "joint", true}, {"A2", "absolute", false},
                                 {"A3", "absolute", true}};

constexpr double kBaumgarte = 50.0;  // [1/s] A: α = 0.1/h at the paper's h = 2 ms, fixed for all runs
// The implicit reference's tolerance (its Newton then at 1e-10): at the scenarios' 1e-3 Newton runs at 1e-6, and
// in absolute coordinates its errors add up to a floor of ~4e-5 of the motion whatever the step (riser_integration).
constexpr double kImplicitReferenceTolerance = 1e-7;

// The parameters a reference run of `method` uses.
RiserParameters referenceParameters(RiserParameters p, const std::string& method) {
  if (method == "implicit") p.tolerance = kImplicitReferenceTolerance;
  return p;
}

struct Run {
  std::vector<Vec3> mid;  // [m] point at s = L/2 at every output time
  double cpu = 0.0;       // [s]
  long rhs = 0;
  long steps = 0;
};

// The scene's implicit generalized-α path (riser_integration: chart, Newton, recorder), step `step`:
// the probe at L/2 from the recorder's history (≈ 2000 samples), interpolated linearly to the 0.2 s
// output times (interpolation error ≈ (ωΔt)²/8 ≈ 1e-5 of the motion at Δt = 0.018 s, T = 10 s).
// "auto" (scene's choice): integrator "auto" at tolerance `step`, the step its plan picks.
Run integrateImplicit(const RiserModel& m, RiserParameters p, const StaticSolution& s, double step, bool automatic) {
  p.integrator = automatic ? "auto" : "implicit";
  p.time_step = automatic ? 0.0 : step;
  if (automatic) p.tolerance = step;
  p.probes = {{0.5 * p.length}};
  p.stress_times.clear();
  // Frames are the implicit integrator's chunk ends (Newton matrix refreshed per chunk); 2 per period
  // keeps them from capping the step.
  p.frame_count = std::max(2, static_cast<int>(std::ceil(2 * p.end_time / p.motion_period)));
  RunContext ctx;
  Eigen::VectorXd y = restState(m, s.orientation, s.top);
  const IntegrationPlan plan = planIntegration(m, p);
  RiserRecorder recorder(m, p);
  recorder.sample(0.0, y, true, std::string("profile_static"));
  Run run;
  const double t0 = bench::threadCpuSeconds();
  const SolverStats st = integrateRiser(m, p, plan, y, recorder, ctx);
  run.cpu = bench::threadCpuSeconds() - t0;
  run.rhs = st.rhs_evaluations;
  run.steps = st.steps;
  const Results r = recorder.finish(st, s);
  const Table* h = r.findTable("history");
  const auto& time = h->find("time")->values;
  const Column* d[3] = {h->find("probe_dx"), h->find("probe_dy"), h->find("probe_dz")};
  std::size_t j = 0;
  for (double t = 0.0; t <= p.end_time + 1e-9; t += 0.2) {
    while (j + 2 < time.size() && time[j + 1] < t) ++j;
    const double w = std::clamp((t - time[j]) / (time[j + 1] - time[j]), 0.0, 1.0);
    Vec3 v;
    for (int c = 0; c < 3; ++c) v[c] = (1 - w) * d[c]->values[j] + w * d[c]->values[j + 1];
    run.mid.push_back(v);
  }
  return run;
}

Run integrate(const RiserParameters& p, const std::string& method, double value) {
  const RiserModel m = buildRiserModel(p);
  RunContext ctx;
  const StaticSolution s = solveStatics(m, ctx);
  Eigen::VectorXd y = restState(m, s.orientation, s.top);
  RiserWorkspace ws = makeWorkspace(m, m.formulation == Formulation::Absolute ? kBaumgarte : 0.0);
  OdeRhs rhs = [&](double t, const Eigen::VectorXd& x, Eigen::VectorXd& dx) { evaluateRhs(m, ws, t, x, dx); };
  RiserPose pose;
  pose.resize(m.segmentCount());
  Run run;
  const auto [seg, xi] = m.locate(0.5 * m.length);
  OdeObserver observe = [&](double t, const Eigen::VectorXd& x) {
    poseFromState(m, t, x, pose);
    run.mid.push_back(pose.position[seg] + xi * pose.tangent(seg));
  };
  OdeOptions o;
  o.t0 = 0.0;
  o.t1 = p.end_time;
  o.output_interval = 0.2;
  o.state_name = [&](Eigen::Index k) { return stateComponentName(m, k); };
  OdeStats st;
  if (method == "implicit" || method == "auto") return integrateImplicit(m, p, s, value, method == "auto");
  const double t0 = bench::threadCpuSeconds();
  if (method == "rk4") {
    o.step = value;
    st = integrateRk4(rhs, y, o, ctx, observe);
  } else {
    o.step = 0.0;
    o.rtol = value;
    o.atol = value * 1e-3;
    st = integrateDopri5(rhs, y, o, ctx, observe);
  }
  run.cpu = bench::threadCpuSeconds() - t0;
  run.rhs = st.rhs_evaluations;
  run.steps = st.steps;
  for (std::size_t k = run.mid.size(); k-- > 0;) run.mid[k] -= run.mid[0];  // displacement, as the implicit path
  return run;
}

double relativeError(const Run& a, const Run& ref) {
  if (a.mid.empty() || ref.mid.empty()) return std::numeric_limits<double>::quiet_NaN();
  double scale = 0, err = 0;
  for (std::size_t k = 0; k < std::min(a.mid.size(), ref.mid.size()); ++k) {
    scale = std::max(scale, (ref.mid[k] - ref.mid[0]).norm());
    err = std::max(err, (a.mid[k] - ref.mid[k]).norm());
  }
  return err / std::max(scale, 1e-300);
}

// CPU time of one right-hand side at a straight rest state, averaged over ≥ 0.05 s of evaluations.
double rhsCost(RiserParameters p) {
  p.current_speed_surface = p.current_speed_seabed = 0.0;  // straight start: no statics needed
  const RiserModel m = buildRiserModel(p);
  Eigen::VectorXd y = restState(m, m.initial_orientation, m.initial_top), dy(y.size());
  RiserWorkspace ws = makeWorkspace(m, kBaumgarte);
  long count = 0;
  const double t0 = bench::threadCpuSeconds();
  double t1 = t0;
  do {
    for (int k = 0; k < 20; ++k) evaluateRhs(m, ws, 1.0, y, dy);
    count += 20;
    t1 = bench::threadCpuSeconds();
  } while (t1 - t0 < 0.05);
  return (t1 - t0) / count;
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  double one = 0;
  return in >> one ? std::to_string(one).substr(0, 5) : std::string("unknown");
}

// Estimated CPU seconds of one run, from the measured cost c of one right-hand side at this n (the bench
// skips runs above its budget instead of leaving their rows silently absent). Factors from the n ≤ 200 rows:
// RK4 4 right-hand sides per step plus ≈ 20 % bookkeeping (CPU/(steps·n) 2.2–3.0 µs against 4c/n = 2.0–2.6);
// DOPRI5 is stability-bound like RK4 (1.5–2.5x the steps of RK4 at its limit, 6 evaluations per step);
// the implicit step costs 10–56 c (Newton residuals, O(n) matrix refreshes, step halvings: 60 c taken).
struct Estimate {
  double cpu = 0;    // [s]
  std::string text;  // "N steps × k c, c = X µs"
};

Estimate estimate(const std::string& method, double value, double end_time, double limit, double c, double period) {
  char b[160];
  double steps = 0, per_step = 0;
  if (method == "rk4") steps = std::ceil(end_time / value), per_step = 4 * 1.2;
  else if (method == "dopri5") steps = 2.5 * end_time / limit, per_step = 6 * 1.2;
  else if (method == "auto") steps = std::ceil(end_time / implicitStepForTolerance(Formulation::Joint, period, value)), per_step = 60;
  else steps = std::ceil(end_time / value), per_step = 60;
  std::snprintf(b, sizeof b, "%.0f steps × %.3g right-hand sides of %.1f µs", steps, per_step, 1e6 * c);
  return {steps * per_step * c, b};
}

struct Options {
  std::string out = "riser_work_precision.csv";
  double case5_end = 36.0;
  std::string only = "all";
  std::vector<int> case5_n, cable_n;  // n to run per case
  bool thousand = false;              // an implicit J3 run of case 5 at n = 1000 (error against the finest n)
  bool merge = false;                 // merge the rows into an existing `out` (replacing rows of the same key)
  bool estimate_only = false;         // print the estimated cost of every run, run nothing
  bool skipped_only = false;          // write only the rows skipped for their estimated cost (no integration)
  bool rerun_skipped = false;         // run only the settings whose merged-into row was skipped for cost or is absent
  double budget = 180.0;              // [s] CPU: runs estimated above it are skipped with a note
  double reference_budget = 180.0;    // [s] CPU: the most accurate same-n reference estimated within it is taken
  std::vector<std::string> variants = {"J2", "J3", "A2", "A3"};  // in run order
  std::vector<std::string> methods;   // only these methods (rk4, dopri5, implicit, auto); empty = all
  int finest_n = 0;                   // n of the "finest n" reference if above the largest listed n (0: that n)
};

std::vector<std::string> parseNames(const char* text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::vector<int> parseList(const char* text) {
  std::vector<int> out;
  for (const std::string& item : parseNames(text)) out.push_back(std::atoi(item.c_str()));
  std::sort(out.begin(), out.end());
  return out;
}

Options parseOptions(int argc, char** argv) {
  Options o;
  if (argc > 1) o.out = argv[1];
  const int n_max = argc > 2 ? std::atoi(argv[2]) : 400;
  if (argc > 3) o.case5_end = std::atof(argv[3]);
  if (argc > 4) o.only = argv[4];
  const int cable_n_max = argc > 5 ? std::atoi(argv[5]) : n_max;
  for (int n : {10, 20, 50, 100, 200, 400}) {
    if (n <= n_max) o.case5_n.push_back(n);
    if (n <= cable_n_max) o.cable_n.push_back(n);
  }
  o.thousand = n_max >= 1000;
  if (const char* list = std::getenv("MARIS_BENCH_NLIST")) o.case5_n = parseList(list), o.merge = true;
  if (const char* list = std::getenv("MARIS_BENCH_CABLE_NLIST")) o.cable_n = parseList(list), o.merge = true;
  if (const char* m = std::getenv("MARIS_BENCH_MERGE")) o.merge = std::string(m) == "1";
  if (const char* b = std::getenv("MARIS_BENCH_ROW_BUDGET")) o.budget = o.reference_budget = std::atof(b);
  if (const char* b = std::getenv("MARIS_BENCH_REFERENCE_BUDGET")) o.reference_budget = std::atof(b);
  if (const char* e = std::getenv("MARIS_BENCH_ESTIMATE_ONLY")) o.estimate_only = std::string(e) == "1";
  if (const char* e = std::getenv("MARIS_BENCH_SKIPPED_ONLY")) o.skipped_only = std::string(e) == "1";
  if (const char* e = std::getenv("MARIS_BENCH_RERUN_SKIPPED")) o.rerun_skipped = o.merge = std::string(e) == "1";
  if (const char* v = std::getenv("MARIS_BENCH_VARIANTS")) o.variants = parseNames(v);
  if (const char* m = std::getenv("MARIS_BENCH_METHODS")) o.methods = parseNames(m);
  if (const char* f = std::getenv("MARIS_BENCH_FINEST_N")) o.finest_n = std::atoi(f);
  return o;
}

// The CSV and the markdown tables, merged with the rows already in `out` when merging.
class RowWriter {
 public:
  explicit RowWriter(const Options& o) : out_(o.out) {
    if (!o.merge) return;
    std::ifstream in(out_);
    std::stringstream text;
    text << in.rdbuf();
    if (in) old_ = bench::parseWorkPrecisionRows(text.str());
  }
  void add(const bench::WorkPrecisionRow& row) {
    rows_.push_back(row);
    write(loadAverage() + " (still running)");
  }
  void finish() { write(loadAverage()); }
  // Whether the merged-into CSV has no row of `key`'s case, variant, n, method and setting, or one skipped for
  // its estimated cost.
  bool skippedForCostOrAbsent(const bench::WorkPrecisionRow& key) const {
    const std::string k = bench::workPrecisionKey(key);
    for (const auto& r : old_)
      if (bench::workPrecisionKey(r) == k) return r.note.rfind("skipped: estimated", 0) == 0;
    return true;
  }
  void setHeader(const std::string& header) { header_ = header; }

 private:
  void write(const std::string& load_now) {
    const auto merged = bench::mergeWorkPrecisionRows(old_, rows_);
    std::string csv = bench::workPrecisionHeader();
    for (const auto& r : merged) csv += bench::workPrecisionLine(r);
    writeFileAtomic(out_, csv);  // after every row: a long run can be cut short and still plotted
    const std::string md = (out_.size() > 4 && out_.substr(out_.size() - 4) == ".csv" ? out_.substr(0, out_.size() - 4) : out_) + ".md";
    writeFileAtomic(md, bench::riserWorkPrecisionSummary(merged, header_ + " Load average " + load_start_ +
                                                                     " at the start, " + load_now + " at the end (2-core machine: above ~1 the times may be upper bounds)."));
  }
  std::string out_, header_, load_start_ = loadAverage();
  std::vector<bench::WorkPrecisionRow> old_, rows_;
};

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parseOptions(argc, argv);
  RowWriter writer(opt);
  std::ostringstream header;
  // The rows come from several runs merged into one CSV (each run's settings and load are in the .log); the header
  // names the last one.
  auto list = [](const std::vector<int>& ns) {
    std::string out;
    for (int n : ns) out += (out.empty() ? "" : ", ") + std::to_string(n);
    return out;
  };
  header << "Last run " << (opt.merge ? "(merged into the rows of earlier runs)" : "(full)") << ":";
  if ((opt.only == "all" || opt.only == "case5") && !opt.case5_n.empty())
    header << " case 5 (" << opt.case5_end << " s) n = " << list(opt.case5_n) << ";";
  if ((opt.only == "all" || opt.only == "cable3d") && !opt.cable_n.empty()) header << " cable n = " << list(opt.cable_n) << ";";
  if (opt.finest_n > 0) header << " finest-n reference at n = " << opt.finest_n << ";";
  header << " variants";
  for (const auto& v : opt.variants) header << " " << v;
  header << "; methods " << (opt.methods.empty() ? std::string("all") : "");
  for (std::size_t k = 0; k < opt.methods.size(); ++k) header << (k ? ", " : "") << opt.methods[k];
  header << "; budget " << opt.budget << " s CPU per run, " << opt.reference_budget << " s for a reference.";
  writer.setHeader(header.str());
  const double inf = std::numeric_limits<double>::infinity();
  using Row = bench::WorkPrecisionRow;

  // Part 1: cost of one right-hand side against n (measured in every run, so every run's rows replace the CSV's).
  std::map<std::string, double> rhs_cost;  // variant + n -> [s]
  std::printf("# rhs cost [us] per n: variant n cost cost/n\n");
  for (const Variant& v : kVariants)
    for (int n : {10, 20, 50, 100, 200, 400, 1000}) {
      RiserParameters p = builtin("riser_paper_case5_j3");
      p.segment_count = n;
      p.formulation = v.formulation;
      p.torsion = v.torsion;
      const double c = rhsCost(p);
      rhs_cost[std::string(v.name) + std::to_string(n)] = c;
      if (!opt.estimate_only) {
        Row r{"rhs_cost", v.name, "rhs", n, 0.0, 0, 1, c, 0.0, 0.0, 0, "", ""};
        writer.add(r);
      }
      std::printf("%s %5d %9.2f %7.4f\n", v.name, n, 1e6 * c, 1e6 * c / n);
    }

  // Part 2: work–precision on the two cases.
  struct Case {
    const char* name;
    RiserParameters p;
    std::vector<int> ns;
  };
  std::vector<Case> cases;
  if ((opt.only == "all" || opt.only == "case5") && !opt.case5_n.empty())
    cases.push_back({"case5", builtin("riser_paper_case5_j3"), opt.case5_n});
  if ((opt.only == "all" || opt.only == "cable3d") && !opt.cable_n.empty())
    cases.push_back({"cable3d", builtin("riser_cable_3d_circle"), opt.cable_n});
  for (auto& c : cases)
    if (c.name == std::string("case5")) c.p.end_time = opt.case5_end;
  for (auto& c : cases) {
    const std::vector<int>& ns = c.ns;
    const bool thousand = opt.thousand && c.name == std::string("case5");
    const double period = c.p.motion_period, end = c.p.end_time;
    // Same-n reference, the most accurate one within the budget: DOPRI5 rtol 1e-10 (n ≤ 100); RK4 at 0.2 × its
    // limit (time error < 1e-8 at n = 200); RK4 at 0.45 × (3.1e-8 against 0.2 × for case 5 J3 at n = 200); at 0.9 ×
    // (3.1e-7 there: enough for the implicit rows, ≥ 5e-4); the implicit integrator at T/3200 (error ≈ 43 (h/T)²
    // of the motion: ≤ 4.2e-6).
    struct Reference {
      std::string how, method;
      double value = 0;
      Estimate cost;
    };
    auto chooseReference = [&](const RiserParameters& p, double limit, double c) {
      std::vector<Reference> tiers;
      if (p.segment_count <= 100) tiers.push_back({"dopri5 1e-10", "dopri5", 1e-10, {}});
      tiers.push_back({"rk4 0.2x limit", "rk4", 0.2 * limit, {}});
      tiers.push_back({"rk4 0.45x limit", "rk4", 0.45 * limit, {}});
      tiers.push_back({"rk4 0.9x limit", "rk4", 0.9 * limit, {}});
      tiers.push_back({"implicit T/3200", "implicit", period / 3200, {}});
      for (auto& t : tiers) {
        t.cost = estimate(t.method, t.value, end, limit, c, period);
        if (t.cost.cpu <= opt.reference_budget) return t;
      }
      return Reference{"", "", 0.0, {}};
    };
    auto limitOf = [](const RiserParameters& p) { return 2.8 / highestFrequencyEstimate(buildRiserModel(p)); };
    auto costOf = [&](const Variant& v, int n) {
      const auto it = rhs_cost.find(std::string(v.name) + std::to_string(n));
      return it != rhs_cost.end() ? it->second : rhs_cost.at(std::string(v.name) + "1000") * n / 1000.0;
    };
    const int finest_size = std::max(ns.back(), opt.finest_n);  // the "finest n" reference's n
    RiserParameters pf = c.p;
    pf.segment_count = finest_size;
    pf.formulation = "joint";
    pf.torsion = true;
    const Reference finest_how = chooseReference(pf, limitOf(pf), costOf(kVariants[1], finest_size));
    Run finest;
    if (!opt.estimate_only && !opt.skipped_only && !finest_how.method.empty()) {
      finest = integrate(referenceParameters(pf, finest_how.method), finest_how.method, finest_how.value);
      std::printf("# %s finest reference n = %d (%s): %.2f s CPU, %ld steps\n", c.name, finest_size, finest_how.how.c_str(),
                  finest.cpu, finest.steps);
    }
    for (const std::string& variant_name : opt.variants) {
      const Variant* chosen = nullptr;
      for (const Variant& candidate : kVariants)
        if (variant_name == candidate.name) chosen = &candidate;
      if (!chosen) {
        std::fprintf(stderr, "unknown variant %s (J2, J3, A2, A3)\n", variant_name.c_str());
        return 2;
      }
      const Variant& v = *chosen;
      std::vector<int> sizes = ns;
      if (thousand && std::string(v.name) == "J3") sizes.push_back(1000);
      for (int n : sizes) {
        RiserParameters p = c.p;
        p.segment_count = n;
        p.formulation = v.formulation;
        p.torsion = v.torsion;
        const bool huge = n > finest_size;
        const double limit = limitOf(p);  // RK4 stability estimate
        const double cost = costOf(v, n);
        const bool is_finest = n == finest_size && std::string(v.name) == "J3";
        const Reference ref_how = huge ? Reference{} : is_finest ? finest_how : chooseReference(p, limit, cost);
        std::vector<std::pair<std::string, double>> settings;
        if (!huge)
          settings = {{"rk4", 0.9 * limit},    {"rk4", 0.45 * limit}, {"rk4", 0.225 * limit},
                      {"dopri5", 1e-3},        {"dopri5", 1e-6},      {"dopri5", 1e-8}};
        if (c.name == std::string("case5") && n == 100) settings.push_back({"rk4", 0.002});  // the paper's step
        // Implicit generalized-α of the scene at T/25, T/50, T/100, T/200 (T = top-motion period).
        for (double k : {25.0, 50.0, 100.0, 200.0})
          if (!huge || k == 50.0) settings.push_back({"implicit", period / k});
        // The scene's default choice ("auto") at the tolerance 1e-3 (the target: relative error 1e-3 at L/2).
        if (!huge) settings.push_back({"auto", 1e-3});
        if (!opt.methods.empty())
          std::erase_if(settings, [&](const auto& m) {
            return std::find(opt.methods.begin(), opt.methods.end(), m.first) == opt.methods.end();
          });
        if (opt.rerun_skipped)
          std::erase_if(settings, [&](const auto& m) {
            return !writer.skippedForCostOrAbsent(Row{c.name, v.name, m.first, n, m.second, 0, 0, 0.0, 0.0, 0.0, 0, "", ""});
          });
        if (settings.empty()) continue;  // nothing to run at this n: no same-n reference either
        if (opt.estimate_only) {
          std::printf("# %s %s n = %d reference %s: %.0f s (%s)\n", c.name, v.name, n, ref_how.how.c_str(),
                      ref_how.cost.cpu, ref_how.cost.text.c_str());
          for (const auto& [method, value] : settings) {
            const Estimate e = estimate(method, value, end, limit, cost, period);
            std::printf("  %s %.3e: %.1f s%s\n", method.c_str(), value, e.cpu, e.cpu > opt.budget ? "  SKIP" : "");
          }
          continue;
        }
        Run ref;
        if (is_finest) ref = finest;
        else if (!ref_how.method.empty() && !opt.skipped_only)
          ref = integrate(referenceParameters(p, ref_how.method), ref_how.method, ref_how.value);
        const int finest_n = huge || !finest_how.method.empty() ? finest_size : 0;
        for (const auto& [method, value] : settings) {
          Row row{c.name, v.name, method, n, value, 0, 0, 0.0, inf, inf, finest_n, ref_how.how, ""};
          const Estimate e = estimate(method, value, end, limit, cost, period);
          const bool same_as_ref = method == ref_how.method && value == ref_how.value;
          char why[320];
          if (ref_how.method.empty() && !huge) {
            std::snprintf(why, sizeof why, "skipped: no same-n reference within the budget of %.0f s CPU",
                          opt.reference_budget);
            row.note = why;
          } else if (e.cpu > opt.budget && !same_as_ref) {
            std::snprintf(why, sizeof why, "skipped: estimated %.0f s CPU (%s) > budget %.0f s", e.cpu, e.text.c_str(),
                          opt.budget);
            row.note = why;
          } else if (opt.skipped_only) {
            continue;  // a row that would run: left to a run without MARIS_BENCH_SKIPPED_ONLY
          } else {
            try {
              const Run r = same_as_ref ? ref : integrate(p, method, value);
              row.steps = r.steps, row.rhs_evaluations = r.rhs, row.cpu = r.cpu;
              row.error_same_n = huge ? inf : relativeError(r, ref);
              row.error_finest_n = relativeError(r, finest);
              if (same_as_ref) row.reference += " (this run)";
            } catch (const SolverError& ex) {  // e.g. RK4 above its stability limit: recorded with the reason
              row.note = ex.what();
            }
          }
          writer.add(row);
          std::fputs(bench::workPrecisionLine(row).c_str(), stdout);
          std::fflush(stdout);
        }
      }
    }
  }
  if (!opt.estimate_only) writer.finish();
  std::printf("# written %s and its .md\n", opt.out.c_str());
  return 0;
}
