// Work–precision of the wec scene:
//  1. frequency-domain sweep of 500 frequencies for one float (time per sweep);
//  2. one float, 600 s of regular waves (H = 2 m, ω = 1 rad/s): state-space memory vs direct convolution at
//     several time steps; time, real-time factor and max |θ − θ_ref| against a state-space run at h = 0.005 s,
//     plus the state-space/direct difference at equal step.
// Times are process CPU seconds (bench_clock.hpp), so a loaded machine does not inflate them.
// Writes wec_speed.csv (or argv[1]).
#include <cmath>
#include <cstdio>
#include <string>

#include "core/scenario.hpp"
#include "wec/wec_frequency.hpp"
#include "wec/wec_model.hpp"
#include "wec/wec_time.hpp"
#include "bench_clock.hpp"

using namespace maris::wec;
namespace {

double maxDifference(const TimeDomainResult& a, const TimeDomainResult& b) {
  // Compare at common instants (b may be finer by an integer factor).
  const std::size_t ratio = (b.time.size() - 1) / (a.time.size() - 1);
  double d = 0.0;
  for (std::size_t k = 0; k < a.time.size(); ++k)
    d = std::max(d, std::abs(a.floats[0].theta[k] - b.floats[0].theta[k * ratio]));
  return d;
}
}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "wec_speed.csv";
  WecParameters p;
  std::string csv = "case,time_step,cpu_time,real_time_factor,max_theta_error,error_reference\n";
  csv += "-,s,s,-,rad,-\n";

  // 1. Frequency-domain sweep.
  WecModel model = buildWecModel(p);
  buildRadiation(model, p.kernel_duration, 0.005);
  const int repeats = 20;
  double sink = 0.0;
  const double t0 = maris::bench::processCpuSeconds();
  for (int r = 0; r < repeats; ++r)
    for (int i = 0; i < 500; ++i) sink += std::abs(solveFrequency(model, model.floats[0], 0.1 + 0.01 * i).pitch);
  const double sweep = (maris::bench::processCpuSeconds() - t0) / repeats;
  std::printf("frequency-domain sweep of 500 frequencies: %.3f ms (checksum %.6g)\n", 1e3 * sweep, sink);
  csv += "fd_sweep_500," + std::to_string(0.0) + "," + std::to_string(sweep) + ",,,\n";

  // 2. Time domain.
  const IncidentWaves waves = makeRegularWave(2.0, 1.0, 30.0, 1.0, p.gravity);
  TimeDomainOptions ref;
  ref.duration = 600.0;
  ref.time_step = 0.005;
  ref.output_stride = 1;
  const TimeDomainResult reference = simulateTimeDomain(model, waves, ref, nullptr);
  std::printf("%-12s %8s %10s %12s %14s %14s\n", "memory", "h [s]", "cpu [s]", "x real time", "max|dθ| [rad]",
              "SS-direct");
  for (double h : {0.1, 0.05, 0.025, 0.01}) {
    WecModel m = buildWecModel(p);
    buildRadiation(m, p.kernel_duration, h);
    TimeDomainResult runs[2];
    for (int direct = 0; direct < 2; ++direct) {
      TimeDomainOptions o;
      o.duration = 600.0;
      o.time_step = h;
      o.state_space = direct == 0;
      const double a = maris::bench::processCpuSeconds();
      runs[direct] = simulateTimeDomain(m, waves, o, nullptr);
      const double wall = maris::bench::processCpuSeconds() - a;
      const double err = maxDifference(runs[direct], reference);
      const char* name = direct ? "direct" : "state_space";
      const double between = direct ? maxDifference(runs[0], runs[1]) : 0.0;
      std::printf("%-12s %8.3f %10.4f %12.0f %14.3e %14.3e\n", name, h, wall, 600.0 / wall, err, between);
      csv += std::string(name) + "," + std::to_string(h) + "," + std::to_string(wall) + "," +
             std::to_string(600.0 / wall) + "," + std::to_string(err) + ",state_space_h0.005\n";
    }
    // The augmented formulation with the paper's Newmark two-loop scheme (state-space memory).
    TimeDomainOptions o;
    o.duration = 600.0;
    o.time_step = h;
    o.augmented = o.newmark = true;
    const double a = maris::bench::processCpuSeconds();
    const TimeDomainResult nm = simulateTimeDomain(m, waves, o, nullptr);
    const double wall = maris::bench::processCpuSeconds() - a;
    const double err = maxDifference(nm, reference);
    std::printf("%-12s %8.3f %10.4f %12.0f %14.3e\n", "newmark_aug", h, wall, 600.0 / wall, err);
    csv += "newmark_augmented," + std::to_string(h) + "," + std::to_string(wall) + "," + std::to_string(600.0 / wall) +
           "," + std::to_string(err) + ",state_space_h0.005\n";
  }
  maris::writeFileAtomic(out, csv);
  std::printf("written %s\n", out.c_str());
  return 0;
}
