// Work–precision of the riser scene (issue 10): CPU time against error for the four variants J2, J3,
// A2, A3 and the integrators core/ode.hpp offers (RK4 fixed step as the scene uses, DOPRI5 adaptive),
// on the paper's case 5 (riser_paper_case5_j3: 500 m riser, elliptical top motion, 1 m/s current,
// 36 s) and on a 3D cable case (a 30 m cable whose top whirls on a circle in a current, 10 s).
//   error_same_n:   max over outputs (every 0.2 s) of |r_mid - r_mid,ref| / max |r_mid,ref(t) - r_mid,ref(0)|,
//                   r_mid = the point at s = L/2, reference = DOPRI5 rtol 1e-10 at the same n and variant;
//   error_finest_n: the same against the finest-n J3 reference (discretisation + time error).
//   note:           why a run failed (the solver's message: time, step, quantity); its errors are then inf.
// Also the CPU time of one right-hand side evaluation against n (must grow linearly).
// Times are thread CPU times (the machine may be shared), integration only (statics excluded).
//   bench_riser_work_precision [out.csv] [n_max (default 400; 1000 adds an implicit J3 run at n = 1000)]
//                              [case5_end_time (default 36)] [cases: all | case5 | cable3d]
//                              [cable_n_max (default n_max; the cable's torsion limit makes n = 100 costly)]
// Integrators: RK4 at 0.9, 0.45, 0.225 x its stability estimate, DOPRI5 rtol 1e-3/1e-6/1e-8 (n <= 100), and
// the scene's implicit generalized-alpha (riser_integration) at T/25, T/50, T/100, T/200 of the top-motion period.
// Plot: bench/tools/work_precision_plot (built with the GUI) renders the CSV to PNG with the GUI's plot
// code, e.g. --x cpu_time --y error_same_n --series variant,method --where case=case5 --where n=100.
// Besides the CSV it writes OUT.md (OUT without ".csv"): markdown tables of the right-hand-side cost
// against n, case 5 at n = 100 and the error against n, headed by the load average during the run.
// scripts/bench_riser.sh runs the set the docs quote (build, bench, tables, PNGs).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <limits>
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

using namespace maris;
using namespace maris::riser;

namespace {

RiserParameters builtin(const std::string& id) {
  const auto text = builtinResource("scenarios/riser/" + id + ".json");
  return riserBinder().read(scenarioFromText(std::string(*text)).parameters);
}

// The 3D cable: 30 m steel cable D 0.05 m pinned at a top that moves on a horizontal circle of radius
// 1 m (period 4 s) in a 0.5 m/s current at 45°, free bottom, in water.
RiserParameters cable3d() {
  RiserParameters p;
  p.length = 30.0;
  p.outer_diameter = 0.05;
  p.inner_diameter = 0.0;
  p.water_level = 10.0;
  p.seabed_level = -100.0;
  p.current_speed_surface = p.current_speed_seabed = 0.5;
  p.current_direction = 0.7853981633974483;
  p.top_condition = "pinned";
  p.motion_amplitude_x = p.motion_amplitude_y = 1.0;
  p.motion_period = 4.0;
  p.motion_ramp_time = 2.0;
  p.bottom_condition = "free";
  p.end_time = 10.0;
  return p;
}

struct Variant {
  const char* name;
  const char* formulation;
  bool torsion;
};
constexpr Variant kVariants[] = {{"J2", "joint", false}, {"J3", "joint", true}, {"A2", "absolute", false},
                                 {"A3", "absolute", true}};

constexpr double kBaumgarte = 50.0;  // [1/s] A: α = 0.1/h at the paper's h = 2 ms, fixed for all runs

struct Run {
  std::vector<Vec3> mid;  // [m] point at s = L/2 at every output time
  double cpu = 0.0;       // [s]
  long rhs = 0;
  long steps = 0;
};

// The scene's implicit generalized-α path (riser_integration: chart, Newton, recorder), step `step`:
// the probe at L/2 from the recorder's history (≈ 2000 samples), interpolated linearly to the 0.2 s
// output times (interpolation error ≈ (ωΔt)²/8 ≈ 1e-5 of the motion at Δt = 0.018 s, T = 10 s).
Run integrateImplicit(const RiserModel& m, RiserParameters p, const StaticSolution& s, double step) {
  p.integrator = "implicit";
  p.time_step = step;
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
  const Results r = recorder.finish(st, 0, 0.0);
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
  if (method == "implicit") return integrateImplicit(m, p, s, value);
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

// CPU time of one right-hand side at the static state, averaged over ≥ 0.05 s of evaluations.
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

// One CSV row, kept for the markdown summary.
struct Row {
  std::string case_name, variant, method;
  int n = 0;
  double setting = 0, cpu = 0, error_same_n = 0, error_finest_n = 0;
  long steps = 0;
  std::string note;  // why the run failed ("" if it did not)
};

// A failure message as one CSV cell: commas and line breaks become semicolons and spaces.
std::string csvCell(std::string text) {
  for (char& c : text)
    if (c == ',') c = ';';
    else if (c == '\n' || c == '\r') c = ' ';
  return text;
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  double one = 0;
  return in >> one ? std::to_string(one).substr(0, 5) : std::string("unknown");
}

std::string fmt(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

// Markdown tables of the rows: right-hand-side cost against n, case 5 at n = 100, error against n.
// Settings of the run, for the header: case 5 n ≤ n_max, cable n ≤ cable_n_max.
struct RunSettings {
  int n_max = 0, cable_n_max = 0;
  double case5_end = 0;
};

std::string summary(const std::vector<Row>& rows, const std::string& load_start, const std::string& load_end,
                    const RunSettings& run) {
  const double case5_end = run.case5_end;
  std::ostringstream md;
  md << "Written by `scripts/bench_riser.sh` (bench_riser_work_precision; do not edit by hand). This run: case 5 over "
     << case5_end << " s for n ≤ " << run.n_max << ", the 3D cable for n ≤ " << run.cable_n_max << ".\n"
     << "Default: n ≤ 100 and cable n ≤ 20 (≈ 8–10 min on one quiet core). Opt-in rows: `MARIS_BENCH_NMAX=200` adds "
     << "case 5 at n = 200 (J3 and A2, references by RK4 at 0.2 × its limit; ≈ +4 min), `MARIS_BENCH_CABLE_NMAX=50` "
     << "the cable at n = 50 (≈ +5 min: its torsion limit makes each doubling of n ≈ 4x dearer), e.g. "
     << "`MARIS_BENCH_NMAX=200 MARIS_BENCH_CABLE_NMAX=50 scripts/bench_riser.sh`. Failed runs show the solver's "
     << "message (column `note` of the CSV).\n\n";
  md << "Measured by bench_riser_work_precision; load average " << load_start << " at the start, " << load_end
     << " at the end (2-core machine: above ~1 the times are upper bounds). CPU = thread CPU seconds of the\n"
     << "integration only; error = max |r(L/2) − r_ref(L/2)| / max motion, against the same-n reference.\n\n";
  md << "**Cost of one right-hand side** [µs] (per segment in brackets); linear growth means a constant bracket:\n\n"
     << "| variant | n = 10 | 20 | 50 | 100 | 200 | 400 | 1000 |\n|---|---|---|---|---|---|---|---|\n";
  for (const Variant& v : kVariants) {
    md << "| " << v.name;
    for (const Row& r : rows)
      if (r.case_name == "rhs_cost" && r.variant == v.name)
        md << " | " << fmt("%.1f", 1e6 * r.cpu) << " (" << fmt("%.2f", 1e6 * r.cpu / r.n) << ")";
    md << " |\n";
  }
  md << "\n**Case 5, n = 100, " << case5_end << " s simulated:**\n\n"
     << "| variant | method | step [s] or rtol | steps | CPU [s] | error (same n) | error (finest n) |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows) {
    if (r.case_name != "case5" || r.n != 100) continue;
    md << "| " << r.variant << " | " << r.method << " | " << fmt("%.3g", r.setting) << " | ";
    if (!r.note.empty())
      md << "failed: " << r.note << " | | | |\n";
    else
      md << r.steps << " | " << fmt("%.3f", r.cpu) << " | " << fmt("%.2e", r.error_same_n) << " | "
         << fmt("%.2e", r.error_finest_n) << " |\n";
  }
  md << "\n**Against n** (first stable RK4 row: 0.9 × the stability estimate, else 0.45 ×; error against the finest n):\n\n"
     << "| case | variant | n | step [s] | steps | CPU [s] | CPU/(steps·n) [µs] | error (finest n) |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, bool> seen;
  for (const Row& r : rows) {
    const std::string key = r.case_name + r.variant + std::to_string(r.n);
    if (r.method != "rk4" || r.case_name == "rhs_cost" || seen[key] || !std::isfinite(r.error_same_n)) continue;
    seen[key] = true;
    md << "| " << r.case_name << " | " << r.variant << " | " << r.n << " | " << fmt("%.3g", r.setting) << " | "
       << r.steps << " | " << fmt("%.3f", r.cpu) << " | " << fmt("%.3f", 1e6 * r.cpu / (double(r.steps) * r.n))
       << " | " << fmt("%.2e", r.error_finest_n) << " |\n";
  }
  return md.str();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "riser_work_precision.csv";
  const int n_max = argc > 2 ? std::atoi(argv[2]) : 400;
  const double case5_end = argc > 3 ? std::atof(argv[3]) : 36.0;
  std::string csv = "case,variant,n,method,setting,steps,rhs_evaluations,cpu_time,error_same_n,error_finest_n,note\n"
                    "-,-,-,-,s or -,-,-,s,-,-,-\n";
  char line[320];
  std::vector<Row> rows;
  const std::string load_start = loadAverage();

  // Part 1: cost of one right-hand side against n.
  std::printf("# rhs cost [us] per n: variant n cost cost/n\n");
  for (const Variant& v : kVariants)
    for (int n : {10, 20, 50, 100, 200, 400, 1000}) {
      RiserParameters p = builtin("riser_paper_case5_j3");
      p.segment_count = n;
      p.formulation = v.formulation;
      p.torsion = v.torsion;
      const double c = rhsCost(p);
      std::snprintf(line, sizeof line, "rhs_cost,%s,%d,rhs,0,0,1,%.6e,0,0,\n", v.name, n, c);
      csv += line;
      rows.push_back({"rhs_cost", v.name, "rhs", n, 0.0, c, 0.0, 0.0, 1, ""});
      std::printf("%s %5d %9.2f %7.4f\n", v.name, n, 1e6 * c, 1e6 * c / n);
    }

  // Part 2: work–precision on the two cases.
  struct Case {
    const char* name;
    RiserParameters p;
  };
  const std::string only = argc > 4 ? argv[4] : "all";
  std::vector<Case> cases;
  if (only == "all" || only == "case5") cases.push_back({"case5", builtin("riser_paper_case5_j3")});
  if (only == "all" || only == "cable3d") cases.push_back({"cable3d", cable3d()});
  for (auto& c : cases)
    if (c.name == std::string("case5")) c.p.end_time = case5_end;
  const int cable_n_max = argc > 5 ? std::atoi(argv[5]) : n_max;
  for (auto& c : cases) {
    std::vector<int> ns;
    for (int n : {10, 20, 50, 100, 200, 400})
      if (n <= (c.name == std::string("cable3d") ? cable_n_max : n_max)) ns.push_back(n);
    const bool thousand = n_max >= 1000 && c.name == std::string("case5");  // implicit J3 only, error vs finest n
    // Finest-n reference: J3, DOPRI5 rtol 1e-10 (n ≤ 100) or RK4 at 0.2 × its limit (n ≥ 200, where
    // DOPRI5 is as stability-bound as RK4 but 3x dearer; RK4's time error there is < 1e-8).
    auto reference = [](const RiserParameters& p) {
      if (p.segment_count <= 100) return integrate(p, "dopri5", 1e-10);
      return integrate(p, "rk4", 0.2 * 2.8 / highestFrequencyEstimate(buildRiserModel(p)));
    };
    RiserParameters pf = c.p;
    pf.segment_count = ns.back();
    pf.formulation = "joint";
    pf.torsion = true;
    const Run finest = reference(pf);
    std::printf("# %s finest reference n = %d: %.2f s CPU, %ld steps\n", c.name, ns.back(), finest.cpu, finest.steps);
    const double period = c.p.motion_period;
    for (const Variant& v : kVariants) {
      std::vector<int> sizes = ns;
      if (thousand && std::string(v.name) == "J3") sizes.push_back(1000);
      for (int n : sizes) {
        RiserParameters p = c.p;
        p.segment_count = n;
        p.formulation = v.formulation;
        p.torsion = v.torsion;
        const bool big = n >= 200, huge = n > ns.back();
        if (big && std::string(v.name) != "J3" && std::string(v.name) != "A2") continue;  // keep the bench in minutes
        const Run ref = huge ? Run{} : (n == ns.back() && std::string(v.name) == "J3") ? finest : reference(p);
        const double limit = 2.8 / highestFrequencyEstimate(buildRiserModel(p));  // RK4 stability estimate
        std::vector<std::pair<std::string, double>> settings;
        if (!huge) settings = {{"rk4", 0.9 * limit}, {"rk4", 0.45 * limit}};
        if (!big) settings.insert(settings.end(), {{"rk4", 0.225 * limit}, {"dopri5", 1e-3}, {"dopri5", 1e-6}, {"dopri5", 1e-8}});
        if (c.name == std::string("case5") && n == 100) settings.push_back({"rk4", 0.002});  // the paper's step
        // Implicit generalized-α of the scene at T/25, T/50, T/100, T/200 (T = top-motion period).
        for (double k : {25.0, 50.0, 100.0, 200.0})
          if (!huge || k == 50.0) settings.push_back({"implicit", period / k});
        for (const auto& [method, value] : settings) {
          Run r;
          try {
            r = integrate(p, method, value);
          } catch (const SolverError& e) {  // e.g. RK4 above its stability limit: recorded with the reason, not plotted
            std::snprintf(line, sizeof line, "%s,%s,%d,%s,%.3e,0,0,0,inf,inf,", c.name, v.name, n, method.c_str(), value);
            const std::string reason = csvCell(e.what());
            csv += line + reason + "\n";
            const double inf = std::numeric_limits<double>::infinity();
            rows.push_back({c.name, v.name, method, n, value, 0.0, inf, inf, 0, reason});
            std::printf("%s%s\n", line, reason.c_str());
            continue;
          }
          std::snprintf(line, sizeof line, "%s,%s,%d,%s,%.3e,%ld,%ld,%.4e,%.3e,%.3e,\n", c.name, v.name, n,
                        method.c_str(), value, r.steps, r.rhs, r.cpu, relativeError(r, ref), relativeError(r, finest));
          csv += line;
          rows.push_back({c.name, v.name, method, n, value, r.cpu, relativeError(r, ref), relativeError(r, finest), r.steps, ""});
          writeFileAtomic(out, csv);  // after every row: a long run can be cut short and still plotted
          std::fputs(line, stdout);
          std::fflush(stdout);
        }
      }
    }
  }
  writeFileAtomic(out, csv);
  const std::string md = (out.size() > 4 && out.substr(out.size() - 4) == ".csv" ? out.substr(0, out.size() - 4) : out) + ".md";
  writeFileAtomic(md, summary(rows, load_start, loadAverage(), RunSettings{n_max, cable_n_max, case5_end}));
  std::printf("# written %s and %s\n", out.c_str(), md.c_str());
  return 0;
}
