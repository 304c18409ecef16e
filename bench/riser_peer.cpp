// The peer riser of the comparison with MoorDyn (scenarios riser_peer_tensioned and riser_peer_fixed_height: 100 m
// steel riser, 1 m/s current, top x = 2 sin(2πt/10), 36 s) with `auto` at tolerances 1e-3 and 1e-4 for n = 50…400,
// both top conditions. Error = max over the history of |r(L/2) − r_ref(L/2)| / max |r_ref(L/2, t) − r_ref(L/2, 0)|
// against the finest n run by generalized-α at the step for tolerance 1e-5 (expected time error ≈ 6e-6); for the
// fixed-height top also the top-force swing (max − min over 20–36 s) and its difference from the reference's.
// MoorDyn is not run here: docs/riser.md cites its measured numbers with their conditions.
//   bench_riser_peer [n_list=50,100,200,400]      the table (markdown) on stdout
//   bench_riser_peer rhs [n=100] [evaluations=20000]
//       CPU time of one right-hand side (evaluateRhs) of the tensioned peer riser, J3, at its static shape.
// Times are thread CPU seconds of the integration only; on a shared machine they are upper bounds.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "riser/riser_statics.hpp"
#include "bench_clock.hpp"
#include "riser_bench_run.hpp"

using namespace maris;
using namespace maris::riser;

namespace {

RiserParameters peer(const std::string& top) {
  const std::string path = "scenarios/riser/riser_peer_" + top + ".json";
  return riserBinder().read(scenarioFromText(std::string(*builtinResource(path)), path).parameters);
}

std::pair<double, double> forceRange(const bench::RiserRun& o) {
  double lo = 1e300, hi = -1e300;
  for (std::size_t k = 0; k < o.history.t.size(); ++k)
    if (o.history.t[k] >= 20.0) lo = std::min(lo, o.top_force_z[k]), hi = std::max(hi, o.top_force_z[k]);
  return {lo, hi};
}

int rhsCost(int n, long evaluations) {
  RiserParameters p = peer("tensioned");
  p.segment_count = n;
  const RiserModel m = buildRiserModel(p);
  RunContext ctx;
  const StaticSolution s = solveStatics(m, ctx);
  const Eigen::VectorXd y = restState(m, s.orientation, s.top);
  RiserWorkspace ws = makeWorkspace(m, 1.0);
  Eigen::VectorXd dy(y.size());
  double checksum = 0.0;
  const double t0 = bench::threadCpuSeconds();
  for (long k = 0; k < evaluations; ++k) {
    evaluateRhs(m, ws, 12.0 + 1e-6 * static_cast<double>(k % 7), y, dy);
    checksum += dy[dy.size() / 2];
  }
  const double cpu = bench::threadCpuSeconds() - t0;
  std::printf("n = %d: %.2f us per right-hand side (%.3f us per segment; %ld evaluations; checksum %.6e)\n", n,
              1e6 * cpu / static_cast<double>(evaluations), 1e6 * cpu / static_cast<double>(evaluations) / (n + 1),
              evaluations, checksum);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "rhs")
    return rhsCost(argc > 2 ? std::atoi(argv[2]) : 100, argc > 3 ? std::atol(argv[3]) : 20000);
  std::vector<int> ns;
  std::stringstream list(argc > 1 ? argv[1] : "50,100,200,400");
  for (std::string item; std::getline(list, item, ',');) ns.push_back(std::atoi(item.c_str()));
  std::printf("| top | n | tolerance | method | steps | CPU [s] | error at L/2 (finest n) | top force 20-36 s [MN] |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const std::string top : {"tensioned", "fixed_height"}) {
    RiserParameters ref_p = peer(top);
    ref_p.segment_count = ns.back();
    ref_p.tolerance = 1e-5;
    const bench::RiserRun ref = bench::runRiser(ref_p);
    const auto [ref_lo, ref_hi] = forceRange(ref);
    std::printf("| %s | %d | reference 1e-5 | %s | %ld | %.3f | - | %.3f ... %.3f |\n", top.c_str(), ns.back(),
                ref.stats.method.find("generalized") == 0 ? "implicit" : "RK4", ref.stats.steps, ref.cpu, ref_lo / 1e6, ref_hi / 1e6);
    for (int n : ns)
      for (double tol : {1e-3, 1e-4}) {
        RiserParameters p = peer(top);
        p.segment_count = n;
        p.tolerance = tol;
        const bench::RiserRun o = bench::runRiser(p);
        const auto [lo, hi] = forceRange(o);
        const bool implicit = o.stats.method.find("generalized") == 0;
        std::printf("| %s | %d | %.0e | %s | %ld | %.3f | %.2e | %.3f ... %.3f |\n", top.c_str(), n, tol,
                    implicit ? "implicit" : "RK4", o.stats.steps, o.cpu, bench::probeError(o.history, ref.history, bench::ErrorScale::Excursion), lo / 1e6, hi / 1e6);
        std::fflush(stdout);
      }
  }
  return 0;
}
