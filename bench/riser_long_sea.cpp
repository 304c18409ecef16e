// Work against error of the riser in a long irregular sea: the speed target's case, built from the built-in
// scenario riser_vessel_rao_sea (floater RAOs builtin:chosen_floater_rao.csv, its hang-off point, heading and
// offset, current profile table, Wheeler stretching, 20 s ramp, 1.5 MN tensioner, pinned bottom) with
//   L = 100 m in 100 m of water, n = 100, torsion on, JONSWAP Hs 6 m, Tp 10 s, γ 3.3, 200 components,
//   current rows at 0/20/50/100 m depth (0.8/0.6/0.3/0.1 m/s towards 0/10/30/45°), sea-bed contact off,
//   one probe at L/2, 10 frames.
//   bench_riser_long_sea [duration = 600] [steps = 0.2,0.1,0.05] [reference step = 0.0125]
//       implicit generalized-α at each step STEP over DURATION s; prints steps, residuals, Newton-matrix
//       refreshes, thread CPU seconds, the CPU extrapolated linearly to 3 hours, and the probe error at L/2:
//       max over the ≈ 2000 history samples of |r − r_ref| over the range of the reference's motion (the largest
//       distance between two of its samples). Reference: the same integrator at the reference step with Newton
//       at 1e-10, cached in /tmp/riser_long_sea_<duration>_<step>.csv.
//   bench_riser_long_sea kinematics [repeats = 2000]
//       µs per call at the static shape (t from 30 s on, a new time each call): the wave kinematics at the 3(n + 1)
//       Gauss points point by point (WaveField::kinematics, what the loads called before the batch), batched
//       (WaveKinematicsBatch) with every component and with the riser's truncation (the sea's own batch), and one
//       whole right-hand side (evaluateRhs, with the sea's batch).
//   bench_riser_long_sea halfstep [duration = 10800] [step = 0.06]
//       the run at STEP against the same run at STEP/2 (both at the product's Newton tolerance; the half-step run
//       cached in /tmp/riser_long_sea_half_<duration>_<step>.csv): the error at L/2 / range of STEP against STEP/2,
//       e(h) − e(h/2), and the second-order (Richardson) estimate of STEP's own error, 4/3 of it. With the tight
//       reference of the default mode cached (/tmp/riser_long_sea_<duration>_<step/3>.csv), also both against it.
//   bench_riser_long_sea rk4 DURATION STEP
//       RK4 at STEP against the cached reference of that duration (checks the reference on a short run).
// Times are thread CPU seconds; on a shared machine they are upper bounds. Not a pass/fail test.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "core/ocean_kinematics_batch.hpp"
#include "riser/riser_waves.hpp"
#include "bench_clock.hpp"
#include "riser_bench_run.hpp"

using namespace maris;
using namespace maris::riser;

namespace {

RiserParameters targetCase(double duration) {
  const auto text = builtinResource("scenarios/riser/riser_vessel_rao_sea.json");
  RiserParameters p = riserBinder().read(scenarioFromText(std::string(*text)).parameters);
  p.length = 100.0;
  p.segment_count = 100;
  p.torsion = true;
  p.seabed_level = -100.0;
  p.bottom_z = -100.0;
  p.wave_peak_period = 10.0;
  p.wave_component_count = 200;
  p.current_profile = {{0.0, 0.8, 0.0}, {20.0, 0.6, 10.0}, {50.0, 0.3, 30.0}, {100.0, 0.1, 45.0}};
  p.probes = {{0.5 * p.length}};
  p.stress_times.clear();
  p.frame_count = 10;
  p.end_time = duration;
  p.integrator = "implicit";
  p.tolerance = 1e-3;
  return p;
}

bench::ProbeHistory reference(double duration, double step) {
  std::ostringstream name;
  name << "/tmp/riser_long_sea_" << duration << "_" << step << ".csv";
  bench::ProbeHistory h = bench::readHistory(name.str(), duration);
  if (!h.t.empty()) return h;
  RiserParameters p = targetCase(duration);
  p.time_step = step;
  p.tolerance = 1e-7;  // Newton at 1e-10 (1e-3 of the tolerance, within [1e-10, 1e-6])
  std::fprintf(stderr, "computing the reference (generalized-α, h = %g s, Newton at 1e-10) into %s\n",
               step, name.str().c_str());
  const bench::RiserRun o = bench::runRiser(p);
  std::fprintf(stderr, "reference: %ld steps, %.1f s CPU\n", o.stats.steps, o.cpu);
  bench::writeHistory(name.str(), o.history);
  return o.history;
}

double probeError(const bench::ProbeHistory& a, const bench::ProbeHistory& ref) {
  return bench::probeError(a, ref, bench::ErrorScale::Range);
}

std::vector<double> parseList(const std::string& text) {
  std::vector<double> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) out.push_back(std::atof(item.c_str()));
  return out;
}

void printRow(const char* method, double step, const bench::RiserRun& o, double duration, double error) {
  std::printf("| %s | %g | %.0f | %ld | %ld | %ld | %ld | %.2f | %.1f | %.2e |\n", method, step, 10.0 / step,
              o.stats.steps, o.stats.rejected_steps, o.stats.rhs_evaluations, o.stats.matrix_refreshes, o.cpu,
              o.cpu * 10800.0 / duration, error);
  std::fflush(stdout);
}

// µs per call of the kinematics point by point, batched, and of a whole right-hand side (minimum of 5 rounds).
void timeKinematics(int repeats) {
  RiserParameters p = targetCase(60.0);
  const RiserModel m = buildRiserModel(p);
  RunContext ctx;
  const StaticSolution s = solveStatics(m, ctx);
  const Eigen::VectorXd y = restState(m, s.orientation, s.top);
  RiserWorkspace ws = makeWorkspace(m, 0.0);
  Eigen::VectorXd dy(y.size());
  poseFromState(m, 30.0, y, ws.pose);
  const std::vector<Eigen::Vector3d> points = bench::staticGaussPointsBelowWaterLevel(m);
  const ocean::WaveKinematicsBatch batch(m.sea->field, p.wave_direction_deg * std::numbers::pi / 180.0, p.gravity);
  const ocean::WaveKinematicsBatch& truncated = *m.sea->batch;
  std::vector<ocean::FluidKinematics> out(points.size());
  ocean::WaveKinematicsBatch::Scratch scratch, scratch_truncated;
  double direct = 1e300, batched = 1e300, batched_truncated = 1e300, rhs = 1e300, sink = 0;
  for (int round = 0; round < 5; ++round) {
    double t0 = bench::threadCpuSeconds();
    for (int k = 0; k < repeats / 10; ++k)
      for (std::size_t i = 0; i < points.size(); ++i) sink += m.sea->field.kinematics(points[i], 30.0 + 0.01 * k).velocity.x();
    direct = std::min(direct, (bench::threadCpuSeconds() - t0) / (repeats / 10) * 1e6);
    t0 = bench::threadCpuSeconds();
    for (int k = 0; k < repeats; ++k) {
      batch.evaluate(points.data(), points.size(), 30.0 + 0.01 * k, 1.0, 0.0, scratch, out.data());
      sink += out[0].velocity.x();
    }
    batched = std::min(batched, (bench::threadCpuSeconds() - t0) / repeats * 1e6);
    t0 = bench::threadCpuSeconds();
    for (int k = 0; k < repeats; ++k) {
      truncated.evaluate(points.data(), points.size(), 30.0 + 0.01 * k, 1.0, 0.0, scratch_truncated, out.data());
      sink += out[0].velocity.x();
    }
    batched_truncated = std::min(batched_truncated, (bench::threadCpuSeconds() - t0) / repeats * 1e6);
    t0 = bench::threadCpuSeconds();
    for (int k = 0; k < repeats; ++k) {
      evaluateRhs(m, ws, 30.0 + 0.01 * k, y, dy);
      sink += dy[3];
    }
    rhs = std::min(rhs, (bench::threadCpuSeconds() - t0) / repeats * 1e6);
  }
  std::printf("%zu points x %zu components: point by point %.1f us, batched %.1f us (%.1fx), batched with the "
              "riser's truncation %.1f us (%.1fx), right-hand side %.1f us (%g)\n", points.size(), m.sea->field.size(),
              direct, batched, direct / batched, batched_truncated, direct / batched_truncated, rhs, sink * 0.0);
}

// STEP against STEP/2 over DURATION (the 3-hour error of the speed target).
void halfStep(double duration, double step) {
  std::ostringstream name;
  name << "/tmp/riser_long_sea_half_" << duration << "_" << step << ".csv";
  bench::ProbeHistory half = bench::readHistory(name.str(), duration);
  if (half.t.empty()) {
    RiserParameters p = targetCase(duration);
    p.time_step = step / 2;
    const bench::RiserRun o = bench::runRiser(p);
    printRow("half step", step / 2, o, duration, 0.0);
    bench::writeHistory(name.str(), o.history);
    half = o.history;
  }
  RiserParameters p = targetCase(duration);
  p.time_step = step;
  const bench::RiserRun o = bench::runRiser(p);
  const double difference = probeError(o.history, half);
  printRow("against h/2", step, o, duration, difference);
  std::printf("error at L/2 / range over %g s: h = %g against h/2: %.3e; second-order estimate of h's own error "
              "(4/3 of it): %.3e\n", duration, step, difference, 4.0 / 3.0 * difference);
  std::ostringstream tight;
  tight << "/tmp/riser_long_sea_" << duration << "_" << step / 3 << ".csv";
  const bench::ProbeHistory reference = bench::readHistory(tight.str(), duration);
  if (!reference.t.empty())
    std::printf("against the tight reference at h/3 (%s): h %.3e, h/2 %.3e\n", tight.str().c_str(),
                probeError(o.history, reference), probeError(half, reference));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "halfstep") {
    halfStep(argc > 2 ? std::atof(argv[2]) : 10800.0, argc > 3 ? std::atof(argv[3]) : 0.06);
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "kinematics") {
    timeKinematics(argc > 2 ? std::atoi(argv[2]) : 2000);
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "rk4") {
    const double duration = argc > 2 ? std::atof(argv[2]) : 30.0, step = argc > 3 ? std::atof(argv[3]) : 1e-4;
    const bench::ProbeHistory ref = reference(duration, argc > 4 ? std::atof(argv[4]) : 0.0125);
    RiserParameters p = targetCase(duration);
    p.integrator = "rk4";
    p.time_step = step;
    const bench::RiserRun o = bench::runRiser(p);
    printRow("RK4", step, o, duration, probeError(o.history, ref));
    return 0;
  }
  const double duration = argc > 1 ? std::atof(argv[1]) : 600.0;
  const std::vector<double> steps = parseList(argc > 2 ? argv[2] : "0.2,0.1,0.05");
  const double reference_step = argc > 3 ? std::atof(argv[3]) : 0.0125;
  const bench::ProbeHistory ref = reference(duration, reference_step);
  std::printf("duration %g s, reference generalized-α at h = %g s\n", duration, reference_step);
  std::printf("| kinematics | h [s] | Tp/h | steps | rejected | residuals | matrix refreshes | CPU [s] | CPU for 3 h "
              "[s] | error at L/2 / range |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (double h : steps) {
    RiserParameters p = targetCase(duration);
    p.time_step = h;
    const bench::RiserRun o = bench::runRiser(p);
    printRow("batched", h, o, duration, probeError(o.history, ref));
  }
  return 0;
}
