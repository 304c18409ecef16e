#include "riser/riser_integrator_cost.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "riser/riser_integration.hpp"
#include "riser/riser_waves.hpp"

namespace maris::riser {
namespace {

// Measured weights (bench_riser_auto_cost: case 5 and the peer riser, J3 and A3, n = 20 and 100, minimum of 3
// repeats; the table in docs/riser.md), in right-hand sides: a chart residual is one evaluation plus the chart
// maps (1.69–1.75); a banded solve of the force-space Newton matrix (9(n + 1) unknowns, bandwidth 14) and, in joint
// coordinates, the twin's solve and the map back (A 1.04–1.13, J 1.12–1.20); a refresh's work beside its balance
// evaluations (colouring, the band's assembly and factorisation: 11.7–16.4, median 13.8).
constexpr double kResidualCost = 1.72;
constexpr double kAbsoluteSolveCost = 1.06;
constexpr double kJointSolveCost = 1.12;
constexpr double kFactorisationCost = 13.8;
// One right-hand side per segment [µs] (bench_riser_auto_cost: 0.19–0.21 µs at n = 20 and 100), for the per-step
// times of the method line and the wave weight's conversion.
constexpr double kRhsMicrosecondsPerSegment = 0.20;
// The wave kinematics per Gauss point and wave component [ns] (bench_riser_auto_cost: the batch of the riser's sea,
// phases at every component, depth sums truncated where the short waves have died out: 2.05 ns at n = 100, 2.45 at
// n = 20), converted to right-hand sides by the one above.
constexpr double kWaveNanosecondsPerPointComponent = 2.2;

std::string grouped(double value) {
  const long v = std::lround(value);
  std::string digits = std::to_string(v), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return out;
}

std::string milliseconds(double evaluations, const RiserModel& m) {
  std::ostringstream s;
  s.precision(2);
  s << evaluations * kRhsMicrosecondsPerSegment * m.segmentCount() * 1e-3 << " ms";
  return s.str();
}

}  // namespace

double newtonIterationsPerStep(double newton_tolerance) {
  // 2.5 residuals per step at Newton tolerance 1e-6 (case 5, 50 ms), about one more per two decades tighter.
  const double decades = std::max(0.0, std::log10(1e-6 / std::max(newton_tolerance, 1e-300)));
  return 2.5 + 0.5 * decades;
}

double waveEvaluationCost(const RiserModel& m) {
  if (!m.sea) return 0.0;
  const double points = 3.0 * m.segmentCount(), components = static_cast<double>(m.sea->field.size());
  return points * components * kWaveNanosecondsPerPointComponent * 1e-3 /
         (kRhsMicrosecondsPerSegment * m.segmentCount());
}

double bandedSolveCost(const RiserModel& m) {
  return m.formulation == Formulation::Absolute ? kAbsoluteSolveCost : kJointSolveCost;
}

double matrixRefreshCost(const RiserModel& m) {
  // 2·(9s + 5) + 1 grouped differences and 2 evaluations at the base point (riser_newton), one more for the
  // joint coordinates' twin state; s = 2 with internal flow (its curvature stencil reaches two segments).
  const double reach = m.flow_speed != 0.0 ? 2 : 1;
  const double balances = 2 * (9 * reach + 5) + 3 + (m.formulation == Formulation::Joint ? 1 : 0);
  return balances + kFactorisationCost;
}

IntegratorCost predictImplicitCost(const RiserModel& m, const RiserParameters& p, double step, double newton_tolerance) {
  IntegratorCost c;
  c.step = step;
  c.steps = step > 0 ? p.end_time / step : 0.0;
  const double chunks = std::max(1, p.frame_count) + static_cast<double>(p.stress_times.size());
  const double iterations = newtonIterationsPerStep(newton_tolerance);
  const double waves = waveEvaluationCost(m);
  const double per_step = iterations * (kResidualCost + bandedSolveCost(m)) + waves;
  // The history is sampled between the steps (by interpolation of the state), at all 2000 samples however few
  // the steps are.
  const double per_run = chunks * matrixRefreshCost(m) + static_cast<double>(kHistorySamples) * waves;
  c.evaluations_per_step = c.steps > 0 ? per_step + per_run / c.steps : 0.0;
  return c;
}

IntegratorCost predictRk4Cost(const RiserModel& m, const RiserParameters& p, double step) {
  IntegratorCost c;
  c.step = step;
  c.steps = step > 0 ? p.end_time / step : 0.0;
  const double waves = waveEvaluationCost(m);
  const double per_run = std::min<double>(kHistorySamples, c.steps) * waves;
  c.evaluations_per_step = c.steps > 0 ? 4.0 * (1.0 + waves) + per_run / c.steps : 0.0;
  return c;
}

double rk4AccuracyStep(double period, double end_time, double tolerance) {
  const double omega = 2 * std::numbers::pi / period;
  const double phase = std::max(omega * end_time, 1.0);
  return std::pow(120.0 * std::max(tolerance, 1e-14) / phase, 0.25) / omega;
}

double implicitCostOfRun(const RiserModel& m, const RiserSolverStats& stats, long wave_evaluations) {
  return static_cast<double>(stats.rhs_evaluations) * (kResidualCost + bandedSolveCost(m)) +
         static_cast<double>(stats.matrix_refreshes) * matrixRefreshCost(m) +
         static_cast<double>(wave_evaluations) * waveEvaluationCost(m);
}

double explicitCostOfRun(const RiserModel& m, const RiserSolverStats& stats, long wave_evaluations) {
  return static_cast<double>(stats.rhs_evaluations) + static_cast<double>(wave_evaluations) * waveEvaluationCost(m);
}

std::string explainAutoChoice(const RiserModel& m, bool implicit, const IntegratorCost& implicit_cost,
                              const IntegratorCost& rk4_cost) {
  std::ostringstream s;
  s.precision(2);
  const std::string gen = "implicit generalized-α " + grouped(implicit_cost.steps) + " steps × " +
                          milliseconds(implicit_cost.evaluations_per_step, m);
  const std::string rk4 = "RK4 " + grouped(rk4_cost.steps) + " steps × " + milliseconds(rk4_cost.evaluations_per_step, m);
  s << "auto → " << (implicit ? "implicit generalized-α" : "RK4") << ": predicted " << (implicit ? gen : rk4)
    << " against " << (implicit ? rk4 : gen) << " (" << grouped(implicit_cost.total()) << " against "
    << grouped(rk4_cost.total()) << " right-hand-side evaluations; DOPRI5 ≈ 2.7 × RK4's, stability-bound";
  if (m.sea)
    s << "; waves: " << m.sea->field.size() << " components at " << 3 * m.segmentCount()
      << " Gauss points ≈ " << waveEvaluationCost(m)
      << " right-hand sides per evaluation, at each of RK4's 4 evaluations per step, once per implicit step";
  s << ")";
  return s.str();
}

}  // namespace maris::riser
