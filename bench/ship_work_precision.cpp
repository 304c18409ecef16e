// Work–precision of Michell's wave resistance on the Wigley hull: run time against error for grid sizes and
// requested tolerances, with the closed-form Kochin path at rtol 1e-11 as the reference; then the cost of a
// whole 0.10–1.00 sweep (step 0.01) on one thread; then a real hull (the built-in Series 60 table) against its
// own 1025 × 201 sampling at rtol 1e-7 (the table, not the theory, is the reference there). Writes a CSV
// (default ship_work_precision.csv).
//   bench_ship_work_precision [out.csv]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "ship/hull_form.hpp"
#include "ship/hull_offsets.hpp"
#include "ship/michell_resistance.hpp"
#include "ship/resistance_sweep.hpp"
#include "bench_clock.hpp"

using namespace maris::ship;

namespace {

constexpr double kL = 1.0, kB = 0.1, kT = 0.0625, kG = 9.81, kRho = 1000.0;

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

double exactResistance(double fn) {
  WigleyKochin k(kL, kB, kT);
  MichellSettings s;
  s.relative_tolerance = 1e-11;
  return michellWaveResistance(k, fn * std::sqrt(kG * kL), kG, kRho, s).resistance;
}


}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "ship_work_precision.csv";
  std::string csv = "case,froude,stations,waterlines,rtol,time_s,cpu_s,rel_error,rel_error_estimate,evaluations\n";
  char line[256];

  // Single speeds: grid × tolerance.
  const std::vector<std::pair<int, int>> grids = {{65, 13}, {129, 25}, {257, 51}, {513, 101}};
  for (double fn : {0.1, 0.2, 0.35, 0.5, 1.0}) {
    const double exact = exactResistance(fn), U = fn * std::sqrt(kG * kL);
    for (const auto& [nx, nz] : grids) {
      GridKochin kochin(sampleHull(makeParametricHull(kL, kB, kT), nx, nz));
      for (double rtol : {1e-2, 1e-3, 1e-4, 1e-6}) {
        MichellSettings s;
        s.relative_tolerance = rtol;
        int repeats = 0;
        WaveResistance r;
        const double c0 = maris::bench::processCpuSeconds();
        const auto t0 = std::chrono::steady_clock::now();
        auto t1 = t0;
        do {
          r = michellWaveResistance(kochin, U, kG, kRho, s);
          ++repeats;
          t1 = std::chrono::steady_clock::now();
        } while (seconds(t0, t1) < 0.05);
        std::snprintf(line, sizeof line, "single,%.2f,%d,%d,%.0e,%.6e,%.6e,%.4e,%.4e,%ld\n", fn, nx, nz, rtol,
                      seconds(t0, t1) / repeats, (maris::bench::processCpuSeconds() - c0) / repeats, (r.resistance - exact) / exact, r.error_estimate / r.resistance,
                      r.evaluations);
        csv += line;
        std::fputs(line, stdout);
      }
    }
  }

  // Whole curve 0.10–1.00 step 0.01 on one thread.
  std::vector<double> fns, speeds, exact;
  for (int i = 0; i <= 90; ++i) {
    fns.push_back(0.1 + 0.01 * i);
    speeds.push_back(fns.back() * std::sqrt(kG * kL));
    exact.push_back(exactResistance(fns.back()));
  }
  for (const auto& [nx, nz] : std::vector<std::pair<int, int>>{{129, 25}, {257, 51}}) {
    for (double rtol : {1e-3, 1e-4}) {
      const HullGrid grid = sampleHull(makeParametricHull(kL, kB, kT), nx, nz);
      MichellSettings s;
      s.relative_tolerance = rtol;
      const double c0 = maris::bench::processCpuSeconds();
      const auto t0 = std::chrono::steady_clock::now();
      const auto r = waveResistanceSweep([&] { return std::make_unique<GridKochin>(grid); }, speeds, kG, kRho, s, 1,
                                         nullptr, "sweep");
      const auto t1 = std::chrono::steady_clock::now();
      const double cpu = maris::bench::processCpuSeconds() - c0;
      double worst = 0, worst_estimate = 0;
      long evaluations = 0;
      for (std::size_t i = 0; i < r.size(); ++i) {
        worst = std::max(worst, std::abs(r[i].resistance - exact[i]) / exact[i]);
        worst_estimate = std::max(worst_estimate, r[i].error_estimate / r[i].resistance);
        evaluations += r[i].evaluations;
      }
      std::snprintf(line, sizeof line, "sweep_0.10-1.00,all,%d,%d,%.0e,%.6e,%.6e,%.4e,%.4e,%ld\n", nx, nz, rtol,
                    seconds(t0, t1), cpu, worst, worst_estimate, evaluations);
      csv += line;
      std::fputs(line, stdout);
    }
  }
  // Real hull: Series 60 C_B 0.60 (Todd's table, PCHIP-interpolated), error against the finest sampling.
  const auto table = maris::builtinResource("data/ship/series60_cb060_offsets.csv");
  if (table) {
    const HullForm s60 = makeOffsetsHull("series60", parseOffsetsCsv(*table, "series60"), 3.048);
    for (double fn : {0.08, 0.15, 0.2, 0.3}) {
      const double U = fn * std::sqrt(kG * s60.length_pp);
      MichellSettings fine;
      fine.relative_tolerance = 1e-7;
      GridKochin reference_kochin(sampleHull(s60, 1025, 201));
      const double reference = michellWaveResistance(reference_kochin, U, kG, kRho, fine).resistance;
      for (const auto& [nx, nz] : std::vector<std::pair<int, int>>{{129, 25}, {257, 51}, {513, 101}}) {
        GridKochin kochin(sampleHull(s60, nx, nz));
        MichellSettings s;
        s.relative_tolerance = 1e-4;
        const double c0 = maris::bench::processCpuSeconds();
        const auto t0 = std::chrono::steady_clock::now();
        const WaveResistance r = michellWaveResistance(kochin, U, kG, kRho, s);
        const auto t1 = std::chrono::steady_clock::now();
        std::snprintf(line, sizeof line, "series60,%.2f,%d,%d,1e-04,%.6e,%.6e,%.4e,%.4e,%ld\n", fn, nx, nz,
                      seconds(t0, t1), maris::bench::processCpuSeconds() - c0, (r.resistance - reference) / reference, r.error_estimate / r.resistance,
                      r.evaluations);
        csv += line;
        std::fputs(line, stdout);
      }
    }
  }
  maris::writeFileAtomic(out, csv);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
