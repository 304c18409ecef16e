// Cost of the riser's natural modes against n: the shift-invert Arnoldi solver of the banded pencil
// (riser_modes_krylov) and, where it is affordable, the dense solver it replaces above n = 199 (riser_modes).
//   bench_riser_modes_cost [COUNT] [N...]
//       The default riser (bent by its current, torsion on) with n = N segments (default 100 150 199 200 500 1000
//       2000), the COUNT lowest modes (default 10). Prints per n: CPU seconds of the statics, of the Krylov modes
//       and (n ≤ 199) of the dense modes, the Krylov solver's restarts and operator applications, ω₁, and the
//       largest relative difference of the COUNT frequencies between the two solvers.
// Times are thread CPU seconds; on a shared machine they are upper bounds. Not a pass/fail test.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "riser/riser_modes_krylov.hpp"
#include "riser/riser_scene.hpp"
#include "bench_clock.hpp"

using namespace maris;
using namespace maris::riser;

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 10;
  std::vector<int> sizes;
  for (int a = 2; a < argc; ++a) sizes.push_back(std::atoi(argv[a]));
  if (sizes.empty()) sizes = {100, 150, 199, 200, 500, 1000, 2000};
  std::printf("%6s %10s %10s %10s %9s %9s %14s %12s\n", "n", "statics_s", "krylov_s", "dense_s", "restarts",
              "op_appl", "omega_1", "max_rel_diff");
  for (int n : sizes) {
    RiserParameters p;
    p.segment_count = n;
    p.end_time = 0.0;
    p.stress_times.clear();
    const RiserModel m = buildRiserModel(p);
    RunContext context;
    double t0 = bench::threadCpuSeconds();
    const StaticSolution statics = solveStatics(m, context);
    const double statics_s = bench::threadCpuSeconds() - t0;
    std::string method;
    t0 = bench::threadCpuSeconds();
    const RiserModes krylov = computeModesKrylov(m, statics, count, context, &method);
    const double krylov_s = bench::threadCpuSeconds() - t0;
    long restarts = 0, applications = 0;
    const std::size_t at = method.find(" restarts");
    if (at != std::string::npos) {
      std::sscanf(method.c_str() + method.rfind(", ", at) + 2, "%ld", &restarts);
      std::sscanf(method.c_str() + method.find(", ", at) + 2, "%ld", &applications);
    }
    double dense_s = NAN, difference = NAN;
    if (n <= kDenseModesMaxSegments) {
      t0 = bench::threadCpuSeconds();
      const RiserModes dense = computeModes(m, statics, count);
      dense_s = bench::threadCpuSeconds() - t0;
      difference = 0;
      const std::size_t k_max = std::min(dense.frequencies.size(), krylov.frequencies.size());
      for (std::size_t k = 0; k < k_max; ++k)
        difference = std::max(difference, std::abs(krylov.frequencies[k] / dense.frequencies[k] - 1));
    }
    std::printf("%6d %10.3f %10.3f %10.3f %9ld %9ld %14.10f %12.2e\n", n, statics_s, krylov_s, dense_s, restarts,
                applications, krylov.frequencies.empty() ? NAN : krylov.frequencies[0], difference);
    std::fflush(stdout);
  }
  return 0;
}
