// Work–precision of the riser scene (issue 10): CPU time against error for the four variants J2, J3,
// A2, A3 and the integrators core/ode.hpp offers (RK4 fixed step as the scene uses, DOPRI5 adaptive),
// on the paper's case 5 (riser_paper_case5_j3: 500 m riser, elliptical top motion, 1 m/s current,
// 36 s) and on a 3D cable case (a 30 m cable whose top whirls on a circle in a current, 10 s).
//   error_same_n:   max over outputs (every 0.2 s) of |r_mid - r_mid,ref| / max |r_mid,ref(t) - r_mid,ref(0)|,
//                   r_mid = the point at s = L/2, reference = DOPRI5 rtol 1e-10 at the same n and variant;
//   error_finest_n: the same against the finest-n J3 reference (discretisation + time error).
// Also the CPU time of one right-hand side evaluation against n (must grow linearly).
// Times are thread CPU times (the machine may be shared), integration only (statics excluded).
//   bench_riser_work_precision [out.csv] [n_max (default 400)] [case5_end_time (default 36)]
// Plot: maris-cli has no CSV plotting command; columns are in the Maris CSV layout (names, units,
// data), so any plotting tool reads them; docs/riser.md has the measured tables.
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/ode.hpp"
#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_statics.hpp"

using namespace maris;
using namespace maris::riser;

namespace {

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

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
  const double t0 = cpuSeconds();
  OdeStats st;
  if (method == "rk4") {
    o.step = value;
    st = integrateRk4(rhs, y, o, ctx, observe);
  } else {
    o.step = 0.0;
    o.rtol = value;
    o.atol = value * 1e-3;
    st = integrateDopri5(rhs, y, o, ctx, observe);
  }
  run.cpu = cpuSeconds() - t0;
  run.rhs = st.rhs_evaluations;
  run.steps = st.steps;
  return run;
}

double relativeError(const Run& a, const Run& ref) {
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
  const double t0 = cpuSeconds();
  double t1 = t0;
  do {
    for (int k = 0; k < 20; ++k) evaluateRhs(m, ws, 1.0, y, dy);
    count += 20;
    t1 = cpuSeconds();
  } while (t1 - t0 < 0.05);
  return (t1 - t0) / count;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "riser_work_precision.csv";
  const int n_max = argc > 2 ? std::atoi(argv[2]) : 400;
  const double case5_end = argc > 3 ? std::atof(argv[3]) : 36.0;
  std::string csv = "case,variant,n,method,setting,steps,rhs_evaluations,cpu_time,error_same_n,error_finest_n\n"
                    "-,-,-,-,s or -,-,-,s,-,-\n";
  char line[320];

  // Part 1: cost of one right-hand side against n.
  std::printf("# rhs cost [us] per n: variant n cost cost/n\n");
  for (const Variant& v : kVariants)
    for (int n : {10, 20, 50, 100, 200, 400, 1000}) {
      RiserParameters p = builtin("riser_paper_case5_j3");
      p.segment_count = n;
      p.formulation = v.formulation;
      p.torsion = v.torsion;
      const double c = rhsCost(p);
      std::snprintf(line, sizeof line, "rhs_cost,%s,%d,rhs,0,0,1,%.6e,0,0\n", v.name, n, c);
      csv += line;
      std::printf("%s %5d %9.2f %7.4f\n", v.name, n, 1e6 * c, 1e6 * c / n);
    }

  // Part 2: work–precision on the two cases.
  struct Case {
    const char* name;
    RiserParameters p;
  };
  std::vector<Case> cases = {{"case5", builtin("riser_paper_case5_j3")}, {"cable3d", cable3d()}};
  cases[0].p.end_time = case5_end;
  std::vector<int> ns;
  for (int n : {10, 20, 50, 100, 200, 400})
    if (n <= n_max) ns.push_back(n);
  for (auto& c : cases) {
    // Finest-n reference: J3, DOPRI5 rtol 1e-10.
    RiserParameters pf = c.p;
    pf.segment_count = ns.back();
    pf.formulation = "joint";
    pf.torsion = true;
    const Run finest = integrate(pf, "dopri5", 1e-10);
    std::printf("# %s finest reference n = %d: %.2f s CPU, %ld steps\n", c.name, ns.back(), finest.cpu, finest.steps);
    for (const Variant& v : kVariants)
      for (int n : ns) {
        RiserParameters p = c.p;
        p.segment_count = n;
        p.formulation = v.formulation;
        p.torsion = v.torsion;
        const bool big = n >= 200;
        if (big && std::string(v.name) != "J3" && std::string(v.name) != "A2") continue;  // keep the bench in minutes
        const Run ref = (n == ns.back() && std::string(v.name) == "J3") ? finest : integrate(p, "dopri5", 1e-10);
        const double limit = 2.8 / highestFrequencyEstimate(buildRiserModel(p));  // RK4 stability estimate
        std::vector<std::pair<std::string, double>> settings = {{"rk4", 0.9 * limit}, {"rk4", 0.45 * limit},
                                                                {"dopri5", 1e-3}, {"dopri5", 1e-6}};
        if (!big) settings.push_back({"rk4", 0.225 * limit}), settings.push_back({"dopri5", 1e-8});
        if (c.name == std::string("case5") && n == 100) settings.push_back({"rk4", 0.002});  // the paper's step
        for (const auto& [method, value] : settings) {
          Run r;
          try {
            r = integrate(p, method, value);
          } catch (const SolverError& e) {  // RK4 above its stability limit: recorded, not plotted
            std::snprintf(line, sizeof line, "%s,%s,%d,%s,%.3e,0,0,0,inf,inf\n", c.name, v.name, n, method.c_str(), value);
            csv += line;
            std::printf("%s # %s\n", line, e.what());
            continue;
          }
          std::snprintf(line, sizeof line, "%s,%s,%d,%s,%.3e,%ld,%ld,%.4e,%.3e,%.3e\n", c.name, v.name, n,
                        method.c_str(), value, r.steps, r.rhs, r.cpu, relativeError(r, ref), relativeError(r, finest));
          csv += line;
          std::fputs(line, stdout);
          std::fflush(stdout);
        }
      }
  }
  writeFileAtomic(out, csv);
  std::printf("# written %s\n", out.c_str());
  return 0;
}
