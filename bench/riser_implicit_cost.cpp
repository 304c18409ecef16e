// Cost of the riser's implicit integrator and statics against n (the design target: O(n) per right-hand side in both
// formulations), on the paper's case 5 (riser_paper_case5_j3: n = 100, torsion, 36 s, 72 frames).
//   bench_riser_implicit_cost implicit VARIANT STEP [end_time] [reference.csv]
//       VARIANT J3/J2/A3/A2; the scene's implicit path (riser_integration) at step STEP; prints CPU seconds of
//       the integration, steps, residual evaluations and the probe error at L/2: max over the ≈ 2000 history
//       samples of |r − r_ref| / max |r_ref(t) − r_ref(0)|, reference = J3 RK4 at the paper's h = 2 ms
//       (computed once and cached in reference.csv, default /tmp/riser_case5_reference.csv). Environment
//       RISER_TOLERANCE overrides solver.tolerance (the Newton tolerance of the implicit integrator),
//       RISER_BAUMGARTE the stabilisation rate α [1/s] of the constraints (default 1/h).
//   bench_riser_implicit_cost statics N [VARIANT]
//       CPU seconds of solveStatics for case 5 (L = 500 m) with n = N elements.
// Times are thread CPU seconds; on a shared machine they are upper bounds. Not a pass/fail test.

#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "riser/riser_statics.hpp"
#include "bench_clock.hpp"
#include "riser_bench_run.hpp"

using namespace maris;
using namespace maris::riser;

namespace {

RiserParameters case5(const std::string& variant) {
  const auto text = builtinResource("scenarios/riser/riser_paper_case5_j3.json");
  RiserParameters p = riserBinder().read(scenarioFromText(std::string(*text)).parameters);
  p.formulation = variant[0] == 'A' ? "absolute" : "joint";
  p.torsion = variant[1] == '3';
  p.probes = {{0.5 * p.length}};
  return p;
}

bench::ProbeHistory reference(const std::string& path, double end_time) {
  bench::ProbeHistory h = bench::readHistory(path, end_time);
  if (!h.t.empty()) return h;
  RiserParameters p = case5("J3");
  p.integrator = "rk4";
  p.time_step = 0.002;
  p.end_time = end_time;
  std::fprintf(stderr, "computing the RK4 reference (h = 2 ms) into %s\n", path.c_str());
  h = bench::runRiser(p).history;
  bench::writeHistory(path, h);
  return h;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "implicit";
  if (mode == "statics") {
    const int n = argc > 2 ? std::atoi(argv[2]) : 100;
    RiserParameters p = case5(argc > 3 ? argv[3] : "J3");
    p.segment_count = n;
    const RiserModel m = buildRiserModel(p);
    RunContext ctx;
    const double t0 = bench::threadCpuSeconds();
    const StaticSolution s = solveStatics(m, ctx);
    std::printf("statics n=%d cpu=%.3f s iterations=%d load_steps=%d residual=%.2e\n", n, bench::threadCpuSeconds() - t0,
                s.iterations, s.load_steps, s.residual);
    return 0;
  }
  const std::string variant = argc > 2 ? argv[2] : "J3";
  const double step = argc > 3 ? std::atof(argv[3]) : 0.05;
  RiserParameters p = case5(variant);
  if (argc > 4) p.end_time = std::atof(argv[4]);
  const bench::ProbeHistory ref = reference(argc > 5 ? argv[5] : "/tmp/riser_case5_reference.csv", p.end_time);
  p.integrator = "implicit";
  p.time_step = step;
  if (const char* tol = std::getenv("RISER_TOLERANCE")) p.tolerance = std::atof(tol);
  const bench::RiserRun o = bench::runRiser(p, [](IntegrationPlan& plan) {
    if (const char* rate = std::getenv("RISER_BAUMGARTE")) plan.stabilisation_rate = std::atof(rate);
  });
  std::printf("%s h=%g cpu=%.3f s steps=%ld rejected=%ld residuals=%ld error=%.3e\n", variant.c_str(), step, o.cpu,
              o.stats.steps, o.stats.rejected_steps, o.stats.rhs_evaluations,
              bench::probeError(o.history, ref, bench::ErrorScale::Excursion));
  return 0;
}
