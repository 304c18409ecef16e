// Work–precision of the FIV sweep: CPU time of a full sweep (5 h* × 50 speeds, up and down, converged
// limit cycles) against the amplitude error, for convergence tolerances 1e-2…1e-4 and RK4 steps per
// period 20…80, measured against a 320-steps-per-period reference converged to 1e-6. The step is also
// bounded by the force curve's steepness (h·rate <= 1.5), which dominates in galloping, so steps per
// period matter less than the tolerance. Writes fiv_sweep.csv.
//   usage: bench_fiv_sweep [output.csv]
#include <cmath>
#include <fstream>
#include <iostream>

#include "core/ode.hpp"
#include "core/run_context.hpp"
#include "fiv/fiv_sweep.hpp"
#include "bench_clock.hpp"

namespace {

using namespace maris;
using namespace maris::fiv;

struct Run {
  SweepResult sweep;
  double cpu_s = 0.0;
};

Run sweepWith(const FivParameters& p, int steps_per_period, double tolerance) {
  const FivModel model = buildFivModel(p);
  SweepSettings s = sweepSettingsFrom(p);
  s.cycle.steps_per_period = steps_per_period;
  s.cycle.tolerance = tolerance;
  RunContext ctx;
  const double t0 = bench::threadCpuSeconds();
  Run r;
  r.sweep = runSweep(model, s, ctx);
  r.cpu_s = bench::threadCpuSeconds() - t0;
  return r;
}

// Largest relative amplitude difference over converged points of both runs with A > 0.01 D.
double amplitudeError(const SweepResult& a, const SweepResult& ref, double side) {
  double worst = 0.0;
  for (std::size_t b = 0; b < a.branches.size(); ++b)
    for (std::size_t i = 0; i < a.speeds.size(); ++i) {
      const LimitCycle& x = a.branches[b].up[i];
      const LimitCycle& y = ref.branches[b].up[i];
      if (!x.converged || !y.converged || y.amplitude < 0.01 * side) continue;
      worst = std::max(worst, std::abs(x.amplitude / y.amplitude - 1.0));
    }
  return worst;
}

// CPU seconds per RK4 step of the same 6-state system: the scene's fixed-size inlined loop against
// core/ode.hpp integrateRk4 (std::function right-hand side on Eigen::VectorXd, no events).
void compareWithCoreRk4(std::ostream& out) {
  FivParameters p;
  const FivModel model = buildFivModel(p);
  const FivRhs rhs(model, makeOperatingPoint(model, 2.2, kDeep));
  const long steps = 2'000'000;
  const double h = 1e-3;
  State s = seedState(model, 0.5);
  double t0 = bench::threadCpuSeconds();
  for (long i = 0; i < steps; ++i) rhs.step(s, h);
  const double own = (bench::threadCpuSeconds() - t0) / steps;
  const State start = seedState(model, 0.5);
  Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(start.data(), kStateSize);
  OdeOptions options;
  options.t1 = steps * h;
  options.step = h;
  RunContext ctx;
  const OdeRhs f = [&](double, const Eigen::VectorXd& x, Eigen::VectorXd& dx) {
    State a, da;
    for (int i = 0; i < kStateSize; ++i) a[i] = x[i];
    rhs.derivative(a, da);
    for (int i = 0; i < kStateSize; ++i) dx[i] = da[i];
  };
  t0 = bench::threadCpuSeconds();
  integrateRk4(f, y, options, ctx);
  const double core = (bench::threadCpuSeconds() - t0) / steps;
  out << "RK4 step: scene loop " << own * 1e9 << " ns, core integrateRk4 " << core * 1e9 << " ns (final y "
      << s[0] << " vs " << y[0] << " m)\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out_file = argc > 1 ? argv[1] : "fiv_sweep.csv";
  std::ofstream csv(out_file);
  csv << "forcing,steps_per_period,tolerance,cpu_s,limit_cycles,rk4_steps,unconverged,max_amplitude_error\n"
      << "-,-,-,s,-,-,-,-\n";
  for (const char* forcing : {"galloping", "combined"}) {
    FivParameters p;  // paper set: D = 0.09 m, ξ = 0.1, h* = 1.11 … 5.56 and ∞, 50 speeds 0.2–2.5 m/s
    p.forcing = forcing;
    const Run reference = sweepWith(p, 320, 1e-6);
    for (double tolerance : {1e-2, 1e-3, 1e-4})
    for (int spp : {20, 40, 80}) {
      const Run r = sweepWith(p, spp, tolerance);
      const std::size_t cycles = r.sweep.branches.size() * r.sweep.speeds.size() * 2;
      const double err = amplitudeError(r.sweep, reference.sweep, p.side);
      csv << forcing << "," << spp << "," << tolerance << "," << r.cpu_s << "," << cycles << "," << r.sweep.steps << ","
          << r.sweep.unconverged << "," << err << "\n";
      std::cout << forcing << ": tolerance " << tolerance << ", " << spp << " steps/period, " << cycles << " limit cycles in " << r.cpu_s
                << " s CPU (" << r.sweep.steps << " RK4 steps, " << r.sweep.unconverged
                << " unconverged), max amplitude error " << err << "\n";
    }
  }
  compareWithCoreRk4(std::cout);
  std::cout << "written " << out_file << "\n";
  return 0;
}
