#include "riser/riser_integration.hpp"

#include "riser/riser_fatigue.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/checked_count.hpp"
#include "core/errors.hpp"
#include "core/ode.hpp"
#include "core/text_format.hpp"
#include "riser/riser_charted_alpha.hpp"
#include "riser/riser_vessel.hpp"
#include "riser/riser_waves.hpp"
#include "riser/riser_integrator_cost.hpp"

namespace maris::riser {
namespace {

// auto: above this many explicit steps the implicit integrator is used instead.
constexpr double kExplicitStepBudget = 2.0e6;
// Newton's tolerance of the implicit integrator: its share of the asked tolerance or of the step's expected error,
// within [1e-10, 1e-6] (below; the lower bound keeps Newton's test above the residual's round-off).
constexpr double kLooseNewtonTolerance = 1e-6;
constexpr double kTightNewtonTolerance = 1e-10;
constexpr double kNewtonShare = 1e-3;
// RK4 is stable for ωh up to 2√2 ≈ 2.83 on the imaginary axis; with ω_max an estimate, 2.8 is taken as its limit.
constexpr double kRk4StabilityLimit = 2.8;

// Whole steps per frame interval (the integration chunk): a shortened step before each frame changes
// generalized-α's coefficients and costs two Newton-matrix refreshes per chunk (case 5 with its 0.5 s
// frames, A3, n = 400: 53.6 ms took 744 steps, 12 rejected, 10 s CPU; 50 ms 720 steps, 4.0 s). Rounding
// down only makes the step more accurate.
double wholeStepsPerFrame(const RiserParameters& p, double step) {
  if (p.end_time <= 0) return step;
  const double frame = p.end_time / std::max(1, p.frame_count);
  return frame / std::ceil(frame / step - 1e-9);
}

// Newton's tolerance: 1e-3 of the asked tolerance or of the step's expected error, whichever is larger, within
// [1e-10, 1e-6] (integrateImplicit says why).
double newtonTolerance(const RiserParameters& p, double expected_error) {
  return std::clamp(kNewtonShare * std::max(p.tolerance, expected_error), kTightNewtonTolerance,
                    kLooseNewtonTolerance);
}

// One recorder sample after the start: time, whether it is a 3D frame, a profile table name, and whether it is a
// history row (or only a sample of the joint stresses for fatigue).
struct Sample {
  double t = 0.0;
  bool frame = false;
  std::optional<std::string> profile;
  bool history = true;
};

// Frames at k·T/frames, profiles at the stress times, `grid` uniform points in between of which every
// `history_every`-th is a history row (the others sample the joint stresses for fatigue only). RK4: multiples of
// its step `snap`, so every sample is a step point.
std::vector<Sample> sampleSchedule(const RiserParameters& p, long grid, long history_every, double snap) {
  std::vector<Sample> out;
  const double end = p.end_time;
  const int frames = std::max(1, p.frame_count);
  auto snapped = [&](double t) { return snap > 0 ? std::round(t / snap) * snap : t; };
  for (long j = 1; j <= grid; ++j) out.push_back({snapped(end * j / grid), false, std::nullopt, j % history_every == 0});
  for (int k = 1; k <= frames; ++k) out.push_back({snapped(end * k / frames), true, std::nullopt});
  for (double ts : p.stress_times)
    if (ts > 0 && ts <= end) out.push_back({snapped(ts), false, "profile_t" + formatTime(ts)});
  std::sort(out.begin(), out.end(), [](const Sample& a, const Sample& b) { return a.t < b.t; });
  // Merge samples at the same time (within a millionth of the spacing).
  std::vector<Sample> merged;
  const double tol = 1e-6 * end / std::max(grid, 1L);
  for (const auto& s : out) {
    if (s.t <= tol) continue;
    if (!merged.empty() && std::abs(merged.back().t - s.t) <= tol) {
      merged.back().frame = merged.back().frame || s.frame;
      merged.back().history = merged.back().history || s.history;
      if (s.profile) merged.back().profile = s.profile;
    } else {
      merged.push_back(s);
    }
  }
  if (!merged.empty()) {
    merged.back().t = end;
    merged.back().history = true;
  }
  return merged;
}

void accumulate(RiserSolverStats& total, const OdeStats& s) {
  total.steps += s.steps;
  total.rejected_steps += s.rejected_steps;
  total.rhs_evaluations += s.rhs_evaluations;
  total.matrix_refreshes += s.jacobian_evaluations;
  total.error_estimate += s.error_estimate;
}

std::string methodName(const RiserModel& m, const IntegrationPlan& plan, const RiserParameters& p) {
  std::ostringstream s;
  if (plan.method == Integrator::Rk4) s << "RK4, constant step h = " << plan.step << " s";
  if (plan.method == Integrator::Dopri5) s << "DOPRI5 (adaptive), rtol = " << p.tolerance;
  if (plan.method == Integrator::Implicit)
    s << "generalized-α (implicit, ρ∞ = 0.8, " << (m.torsion ? "rotation-vector" : "swing–twist") << " chart), h ≤ "
      << plan.step << " s (equal steps per output interval)";
  s << ", " << (m.formulation == Formulation::Joint ? "joint" : "absolute") << " coordinates"
    << (m.torsion ? " with torsion" : " without torsion");
  if (!plan.reason.empty()) s << " (" << plan.reason << ")";
  return s.str();
}

// What a diverging RK4 run most likely met: a step beyond its stability limit 2.8/ω_max (the plan's estimate of the
// highest mode). Without this the user only saw a non-finite derivative of some state component.
std::string rk4InstabilityNote(const IntegrationPlan& plan) {
  if (plan.method != Integrator::Rk4 || !(plan.highest_frequency > 0)) return {};
  std::ostringstream s;
  s.precision(3);
  const double limit = kRk4StabilityLimit / plan.highest_frequency;
  if (plan.step > limit)
    s << "; the step h = " << plan.step << " s is beyond RK4's stability limit ≈ 2.8/ω_max = " << limit
      << " s (highest mode ω_max ≈ " << plan.highest_frequency
      << " rad/s): the run is unstable; take solver.time_step below the limit (0 = automatic) or solver.integrator = "
         "implicit";
  else
    s << "; RK4 diverged with h = " << plan.step << " s within its estimated stability limit " << limit
      << " s (ω_max ≈ " << plan.highest_frequency << " rad/s is an estimate); try a smaller step or implicit";
  return s.str();
}

// Explicit integrators from sample to sample, projecting the state at every sample.
void integrateExplicit(const RiserModel& m, const RiserParameters& p, const IntegrationPlan& plan,
                       const std::vector<Sample>& samples, Eigen::VectorXd& y, RiserRecorder& recorder,
                       RunContext& context, RiserSolverStats& stats) {
  RiserWorkspace ws = makeWorkspace(m, plan.stabilisation_rate);
  const OdeRhs rhs = [&](double t, const Eigen::VectorXd& state, Eigen::VectorXd& dy) {
    evaluateRhs(m, ws, t, state, dy);
  };
  OdeOptions options;
  options.state_name = [&](Eigen::Index k) { return stateComponentName(m, k); };
  options.rtol = p.tolerance;
  options.atol = p.tolerance;
  options.step = plan.method == Integrator::Rk4 ? plan.step : 0.0;
  if (plan.method == Integrator::Dopri5 && plan.step > 0) options.max_step = plan.step;
  const double end = p.end_time;
  double t = 0.0;
  for (const Sample& s : samples) {
    options.t0 = t;
    options.t1 = s.t;
    // A part of `context`: the integrator sees its cancel flag at every step.
    RunContext chunk = context.part(t / end, s.t / end, "");
    OdeStats st;
    try {
      st = plan.method == Integrator::Rk4 ? integrateRk4(rhs, y, options, chunk) : integrateDopri5(rhs, y, options, chunk);
    } catch (const SolverError& e) {
      throw SolverError(e.quantity(), e.time(), e.step(), e.detail() + rk4InstabilityNote(plan));
    }
    accumulate(stats, st);
    if (plan.method == Integrator::Dopri5 && st.last_step > 0) options.step = st.last_step;
    normaliseState(m, y);
    context.throwIfCancelled();
    t = s.t;
    recorder.sample(t, y, s.frame, s.profile, s.history);
  }
}

// Implicit generalized-α in chunks between frames/profile times; the observer samples in between.
void integrateImplicit(const RiserModel& m, const RiserParameters& p, const IntegrationPlan& plan,
                       const std::vector<Sample>& samples, long grid, long history_every, Eigen::VectorXd& y,
                       RiserRecorder& recorder, RunContext& context, RiserSolverStats& stats) {
  ChartedGeneralizedAlpha integrator(m, plan.stabilisation_rate);
  OdeOptions options;
  // Newton tolerance: 1e-3 of the asked tolerance or of the step's expected error, whichever is larger, within
  // [1e-10, 1e-6]. A loose Newton tolerance spoils the step's own accuracy (case 5, J3, 50 ms: probe error 1.6e-2
  // with Newton at 1e-3, 9.7e-4 at 1e-6, 9.48e-4 at 1e-8). Each accepted iterate is off by up to Newton's
  // tolerance, and in absolute coordinates (where Newton contracts more slowly than in J) these add up to a floor
  // that a smaller step does not lower: 3D cable, A2, n = 50 against J2 at T/3200: 1.8e-4, 9.5e-5, 1.1e-4 of the
  // motion at T/200, T/400, T/800 with Newton at 1e-6; 1.7e-4, 4.2e-5, 1.0e-5 with Newton at 1e-9. Below the
  // step's expected error a tighter Newton buys nothing: case 5 at 50 ms (expected 6e-4 of the motion) with the
  // scenario's tolerance 1e-6 took 3284 residuals in A2 with Newton at 1e-9 against 1441 at 1e-6, same error.
  // The sea's error model (kSeaErrorModel) only reports: Newton keeps the tolerance it was measured with.
  options.rtol = newtonTolerance(p, hasHarmonicTopMotion(m) ? plan.expected_error : 0.0);
  options.atol = options.rtol;
  options.step = plan.step;
  options.min_step = plan.step * 1e-6;
  options.output_interval = p.end_time / static_cast<double>(grid);
  const GeneralizedAlphaOptions alpha;
  const double end = p.end_time;
  // With finer fatigue samples, a history row at the first observer time at or past each history spacing (the
  // observer's times start again at every frame, so they need not fall on the global grid).
  const double history_spacing = options.output_interval * static_cast<double>(history_every);
  double next_history = history_spacing;
  auto is_history = [&](double to) {
    if (history_every == 1) return true;
    if (to < next_history - 0.5 * options.output_interval) return false;
    next_history = (std::floor(to / history_spacing + 0.5) + 1.0) * history_spacing;
    return true;
  };
  double t = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const Sample& s = samples[k];
    if (!s.frame && !s.profile && k + 1 < samples.size()) continue;  // sampled by the observer
    options.t0 = t;
    options.t1 = s.t;
    const OdeStats st = integrator.advance(
        y, options, alpha, context,
        [&](double f, const std::string& stage) { context.progress((t + f * (s.t - t)) / end, stage); },
        [&](double to, const Eigen::VectorXd& state) {
          recorder.sample(to, state, false, std::nullopt, is_history(to));
        });
    accumulate(stats, st);
    t = s.t;
    is_history(t);  // a chunk ends on a frame, a profile time or the end: always a history row
    recorder.sample(t, y, s.frame, s.profile);
  }
}

}  // namespace

std::string formatTime(double t) {
  std::ostringstream s;
  s << t;
  std::string out = s.str();
  std::replace(out.begin(), out.end(), '.', '_');
  return out;
}

double implicitErrorModel(Formulation formulation) {
  // Probe error at L/2 against the same-n reference, / (h/T)² (bench_riser_work_precision, T/100 and T/200):
  // case 5, n = 10…400: absolute 20.8–24.5 (18.6–21.9 before the projection by translation), joint 36.3–42.8;
  // the 3D cable, n = 10…50: 6.0–7.3 and 13.5–19.2. The largest values, rounded up, are taken.
  return formulation == Formulation::Absolute ? 25.0 : 43.0;
}

double implicitStepForTolerance(Formulation formulation, double period, double tolerance) {
  // 0.8: the error model is fitted on one case; aiming at 0.64 tol leaves room for others.
  return 0.8 * period * std::sqrt(std::max(tolerance, 1e-12) / implicitErrorModel(formulation));
}

bool hasHarmonicTopMotion(const RiserModel& m) { return m.motion_amplitude.norm() > 0 && m.top_table.empty(); }

IntegrationPlan planIntegration(const RiserModel& m, const RiserParameters& p) {
  IntegrationPlan plan;
  plan.highest_frequency = highestFrequencyEstimate(m);
  const bool harmonic_top = hasHarmonicTopMotion(m);
  // RK4: half its stability limit 2.8/ω_max, and at least 40 steps per period of the top motion.
  double h_rk4 = 0.5 * kRk4StabilityLimit / plan.highest_frequency;
  if (harmonic_top) h_rk4 = std::min(h_rk4, p.motion_period / 40);
  double h_rk4_run = h_rk4;  // auto: also within the step its accuracy needs
  // Implicit: 50 steps per top period (or per run), unresolved fast modes are damped (ρ∞ = 0.8).
  double h_implicit = harmonic_top ? p.motion_period / 50 : std::max(p.end_time, 1e-9) / 200;
  // Waves load the riser, and move a vessel's top, at their own periods: the same step counts per mean wave period
  // T_m01 (a run's end time over 200 steps took 1.9 s steps in an 8 s wave over 384 s).
  const double wave_period = m.vessel ? m.vessel->mean_period : m.sea ? m.sea->field.meanPeriod() : 0.0;
  if (wave_period > 0) {
    h_rk4 = std::min(h_rk4, wave_period / 40);
    h_implicit = std::min(h_implicit, wave_period / 50);
  }
  const std::string& choice = p.integrator;
  if (choice == "rk4") {
    plan.method = Integrator::Rk4;
  } else if (choice == "dopri5") {
    plan.method = Integrator::Dopri5;
  } else if (choice == "implicit") {
    plan.method = Integrator::Implicit;
  } else {
    // auto: the cheaper of RK4 and generalized-α at the asked tolerance, by predicted right-hand-side
    // evaluations (riser_integrator_cost). RK4 takes the smaller of its stability step and the step whose phase
    // error on the top motion meets the tolerance; the implicit step meets it by the error model
    // (implicitStepForTolerance) and its Newton tolerance follows from that step, as in integrateImplicit.
    // DOPRI5 is stability-bound as well and needs ~2.7x RK4's evaluations (riser_default); it is not chosen.
    if (harmonic_top) {
      h_rk4_run = std::min(h_rk4, rk4AccuracyStep(p.motion_period, p.end_time, p.tolerance));
      h_implicit = std::min(h_implicit, implicitStepForTolerance(m.formulation, p.motion_period, p.tolerance));
    }
    const double h_whole = wholeStepsPerFrame(p, h_implicit);
    const double expected = harmonic_top ? implicitErrorModel(m.formulation) * std::pow(h_whole / p.motion_period, 2) : 0.0;
    const IntegratorCost implicit_cost = predictImplicitCost(m, p, h_whole, newtonTolerance(p, expected));
    const IntegratorCost rk4_cost = predictRk4Cost(m, p, h_rk4_run);
    const bool stiff = rk4_cost.steps > kExplicitStepBudget;
    const bool implicit = stiff || implicit_cost.total() < rk4_cost.total();
    plan.method = implicit ? Integrator::Implicit : Integrator::Rk4;
    plan.rk4_prediction = rk4_cost;
    plan.implicit_prediction = implicit_cost;
    plan.reason = explainAutoChoice(m, implicit, implicit_cost, rk4_cost);
    if (stiff) plan.reason += "; RK4's steps exceed the budget of 2e6";
  }
  if (plan.method == Integrator::Rk4) {
    plan.step = p.time_step > 0 ? p.time_step : h_rk4_run;
    const long steps = p.end_time > 0 ? std::max(1L, checkedCount(p.end_time / plan.step, kMaxTimeSteps,
                                                                  "parameters.solver.time_step",
                                                                  "time steps over solver.end_time"))
                                      : 0;
    if (steps > 0) plan.step = p.end_time / steps;
    // Baumgarte rate of the default step, whatever step is chosen: at α = 0.1/h the term α²Φ (Φ = O(h⁴)) enters
    // at O(h²), and A under RK4 converged at second order (a falling chain's energy error 4.5e-7, 8.1e-8, 1.8e-8
    // at h = 2e-4, 1e-4, 5e-5 s; at a fixed α: 9.4e-8, 6.3e-9, 4.0e-10, fourth order). At the default step
    // it is the same rate; above it (up to the stability limit, twice the default) αh stays ≤ 0.2.
    plan.stabilisation_rate = 0.1 / h_rk4;
  } else if (plan.method == Integrator::Dopri5) {
    plan.step = p.time_step;  // largest step, if given
    plan.stabilisation_rate = 0.1 * plan.highest_frequency / (0.5 * kRk4StabilityLimit);
  } else {
    plan.step = p.time_step > 0 ? p.time_step : wholeStepsPerFrame(p, h_implicit);
    plan.stabilisation_rate = 1.0 / plan.step;
    if (harmonic_top) {
      plan.expected_error = implicitErrorModel(m.formulation) * std::pow(plan.step / p.motion_period, 2);
    } else if (wave_period > 0) {
      plan.expected_error = kSeaErrorModel * std::pow(plan.step / wave_period, 2);
    }
    if (plan.expected_error > 0) {
      std::ostringstream e;
      e.precision(2);
      e << (plan.reason.empty() ? "" : "; ") << "expected probe error ≈ " << plan.expected_error << " of the motion";
      if (!harmonic_top) e << formatText(" (%g (h/T_m01)², T_m01 = %.2g s)", kSeaErrorModel, wave_period);
      plan.reason += e.str();
    }
  }
  return plan;
}

RiserSolverStats integrateRiser(const RiserModel& m, const RiserParameters& p, const IntegrationPlan& plan,
                           Eigen::VectorXd& y, RiserRecorder& recorder, RunContext& context) {
  RiserSolverStats stats;
  stats.error_unit = "-";
  if (p.end_time <= 0) {
    stats.method = "no time integration (solver.end_time = 0): the initial shape" +
                   std::string(p.solve_statics ? " (static equilibrium)" : "") +
                   std::string(p.solve_statics && p.modes ? " and its natural frequencies" : "");
    return stats;
  }
  stats.method = methodName(m, plan, p);
  // The history's 2000 rows; fatigue may sample the joint stresses `history_every` times as often.
  long history_every = 1;
  if (const double fatigue = fatigueSampleInterval(p); fatigue > 0)
    history_every = std::max(1L, static_cast<long>(std::ceil(p.end_time / kHistorySamples / fatigue - 1e-9)));
  long grid = kHistorySamples * history_every;
  double snap = 0.0;
  if (plan.method == Integrator::Rk4) {
    const long steps = std::lround(p.end_time / plan.step);
    if (steps < grid) {  // every step is a sample: a history row every so many steps
      grid = steps;
      history_every = std::max(1L, steps / kHistorySamples);
    }
    snap = plan.step;
  }
  const std::vector<Sample> samples = sampleSchedule(p, grid, history_every, snap);
  if (plan.method == Integrator::Implicit)
    integrateImplicit(m, p, plan, samples, grid, history_every, y, recorder, context, stats);
  else
    integrateExplicit(m, p, plan, samples, y, recorder, context, stats);
  // Generalized-α's own estimate (sum of h²|β − 1/6||Δq̈| relative to the largest coordinate) is dominated by
  // the accelerations of the unresolved, damped fast modes, which leave the motion alone: case 5, joint,
  // 50 ms: 0.45 for a probe error of 1e-3. Where the plan has the measured error model, that is the estimate.
  if (plan.method == Integrator::Implicit && plan.expected_error > 0) stats.error_estimate = plan.expected_error;
  return stats;
}

}  // namespace maris::riser
