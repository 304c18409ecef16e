#include "fiv/fiv_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fiv/fiv_theory.hpp"

namespace maris::fiv {

SweepSettings sweepSettingsFrom(const FivParameters& p) {
  SweepSettings s;
  for (int i = 0; i < p.speed_count; ++i)
    s.speeds.push_back(p.speed_count == 1 ? p.speed_min
                                          : p.speed_min + (p.speed_max - p.speed_min) * i / (p.speed_count - 1));
  s.submergence_ratios = p.submergence_ratios;
  if (p.include_deep) s.submergence_ratios.push_back(kDeep);
  s.sweep_down = p.sweep_down;
  s.up_from_rest = p.up_from_rest;
  s.seed_amplitude_ratio = p.initial_amplitude_ratio;
  s.onset_amplitude_ratio = p.onset_amplitude_ratio;
  s.cycle.steps_per_period = p.steps_per_period;
  s.cycle.tolerance = p.convergence_tolerance;
  s.cycle.max_cycles = p.max_cycles;
  return s;
}

State seedState(const FivModel& model, double amplitude_ratio) {
  State s{};
  s[0] = amplitude_ratio * model.side;
  s[2] = model.viv_on ? 0.1 : 0.0;  // small wake perturbation, grows to |q| ≈ 2 (Facchinetti 2004)
  return s;
}

namespace {

// On the way up the state keeps at least the seed amplitude: a real flow always perturbs the body.
void applySeedFloor(const FivModel& model, double amplitude_ratio, State& s) {
  const double seed = amplitude_ratio * model.side;
  const double amplitude = std::hypot(s[0], s[1] / model.omega_n);
  if (amplitude < seed) {
    if (amplitude > 0.0) {
      s[0] *= seed / amplitude;
      s[1] *= seed / amplitude;
    } else {
      s[0] = seed;
    }
  }
  if (model.viv_on && std::hypot(s[2], s[3]) < 1e-3) s[2] = 0.1;
}

LimitCycle solvePoint(const FivModel& model, double speed, double h_star, const SweepSettings& settings,
                      State& state, RunContext& context) {
  const OperatingPoint op = makeOperatingPoint(model, speed, h_star);
  const FivRhs rhs(model, op);
  return runToLimitCycle(rhs, state, settings.cycle, &context);
}

// The sweep so far (see SweepObserver): finished branches, or the first branch's up-sweep.
SweepResult sweepSoFar(const SweepResult& finished, const SweepBranch& current) {
  SweepResult out = finished;
  if (!out.branches.empty()) return out;
  out.speeds.resize(std::min(out.speeds.size(), current.up.size()));
  SweepBranch climbing = current;
  climbing.down.clear();
  out.branches.push_back(std::move(climbing));
  return out;
}

}  // namespace

SweepResult runSweep(const FivModel& model, const SweepSettings& settings, RunContext& context,
                     const SweepObserver& observe) {
  SweepResult result;
  result.speeds = settings.speeds;
  const std::size_t n_speed = settings.speeds.size();
  const double total = static_cast<double>(settings.submergence_ratios.size() * n_speed * (settings.sweep_down ? 2 : 1));
  double done = 0.0;
  auto account = [&](const LimitCycle& c) {
    result.steps += c.steps;
    result.worst_residual = std::max(result.worst_residual, c.residual);
    if (c.response == ResponseKind::Drifting) ++result.unconverged;
    if (c.response == ResponseKind::Stationary) ++result.stationary;
    context.progress(++done / total, "limit cycles");
  };
  for (double h_star : settings.submergence_ratios) {
    SweepBranch branch;
    branch.submergence_ratio = h_star;
    branch.clearance = std::isfinite(h_star) ? (h_star - 0.5) * model.side : kDeep;
    const double kappa = surfaceFactor(model.gallop_deficit, model.surface_decay, h_star);
    branch.linear_onset_speed = model.galloping_on
                                    ? gallopingOnsetSpeed(model.damping, model.density, model.side, model.length,
                                                          model.curve.initialSlope(), kappa)
                                    : kDeep;
    // Up-sweep from the seed.
    State state = seedState(model, settings.seed_amplitude_ratio);
    for (double speed : settings.speeds) {
      if (settings.up_from_rest) state = seedState(model, settings.seed_amplitude_ratio);
      applySeedFloor(model, settings.seed_amplitude_ratio, state);
      branch.up.push_back(solvePoint(model, speed, h_star, settings, state, context));
      account(branch.up.back());
      if (observe && context.wantsPartialResults()) observe(sweepSoFar(result, branch));
    }
    // Down-sweep continues from the top state.
    if (settings.sweep_down) {
      branch.down.resize(n_speed);
      for (std::size_t i = n_speed; i-- > 0;) {
        branch.down[i] = solvePoint(model, settings.speeds[i], h_star, settings, state, context);
        account(branch.down[i]);
        // The first branch's complete up-sweep (sweepSoFar leaves the unfinished down-sweep out), in case
        // the throttle dropped its last up point.
        if (observe && result.branches.empty() && context.wantsPartialResults()) observe(sweepSoFar(result, branch));
      }
    }
    // Onset: lowest speed from which every higher up-sweep amplitude is at least the threshold.
    for (std::size_t i = n_speed; i-- > 0;) {
      if (branch.up[i].amplitude < settings.onset_amplitude_ratio * model.side) break;
      branch.onset_speed = settings.speeds[i];
    }
    result.branches.push_back(std::move(branch));
    if (observe && context.wantsPartialResults()) observe(result);
  }
  return result;
}

}  // namespace maris::fiv
