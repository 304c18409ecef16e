#include "fiv/fiv_limit_cycle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include "core/checked_count.hpp"
#include "core/errors.hpp"

namespace maris::fiv {

namespace {

// One cycle between two zero up-crossings of y.
struct CycleRecord {
  double period = 0.0;         // [s]
  double amplitude = 0.0;      // [m] half peak-to-peak
  double y_max = 0.0, y_min = 0.0;
  double energy_damper = 0.0;  // [J] ∫cẏ² over the cycle
  double energy_fluid = 0.0;   // [J] ∫Fẏ over the cycle
  double crossing_speed = 0.0; // [m/s] ẏ at the up-crossing that closes the cycle
  double max_tan_alpha = 0.0;
};

// Cubic Hermite value of y at fraction tau of a step of size h.
double hermite(double y0, double v0, double y1, double v1, double h, double tau) {
  const double t2 = tau * tau, t3 = t2 * tau;
  return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + tau) * h * v0 + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * h * v1;
}

// Estimated remaining relative change of a per-cycle quantity x_k (amplitude, crossing speed), assuming
// geometric convergence x_k = x_∞ + C ρ^k with ρ from successive differences (capped at 0.98). The largest
// of the last three differences is used, so that an oscillating approach that happens to pause for one
// cycle is not taken for convergence.
template <class Get>
double remainingDrift(const std::vector<CycleRecord>& cycles, double floor, Get value) {
  const std::size_t n = cycles.size();
  double worst = 0.0;
  for (std::size_t k = n - 3; k < n; ++k) {
    const double d1 = value(cycles[k]) - value(cycles[k - 1]);
    const double d0 = value(cycles[k - 1]) - value(cycles[k - 2]);
    double factor = 1.0;
    if (d0 != 0.0 && d1 / d0 > 0.0) factor = std::max(1.0, std::min(d1 / d0, 0.98) / (1.0 - std::min(d1 / d0, 0.98)));
    worst = std::max(worst, std::abs(d1) * factor);
  }
  return worst / std::max(std::abs(value(cycles[n - 1])), floor);
}

// Relative amplitude change over the last cycle implied by the energy balance: the fluid work minus the
// damper work is the change of mechanical energy E = ½ m_t v² at the up-crossing, and δA/A ≈ δE/(2E).
// On an exact cycle it is zero (paper eqs 8 = 13); what remains is the integration error of the works.
double energyImbalance(const CycleRecord& c, double total_mass) {
  const double energy = 0.5 * total_mass * c.crossing_speed * c.crossing_speed;
  return energy > 0.0 ? std::abs(c.energy_fluid - c.energy_damper) / (2.0 * energy) : 0.0;
}

// |⟨Fẏ⟩ − ⟨cẏ²⟩|/⟨cẏ²⟩ over cycles [first, end): zero on average over a stationary response (eqs 8 = 13),
// so what a window leaves is the error of its power, from the mechanical energy it ends with.
double windowPowerImbalance(const std::vector<CycleRecord>& cycles, std::size_t first) {
  double damper = 0.0, fluid = 0.0;
  for (std::size_t i = first; i < cycles.size(); ++i) {
    damper += cycles[i].energy_damper;
    fluid += cycles[i].energy_fluid;
  }
  return damper > 0.0 ? std::abs(fluid - damper) / damper : 0.0;
}

// Largest RK4 step keeping h·rate <= 1.5 for every |ẏ/U| up to tan_alpha (rate sampled on 17 points).
double stableStep(const FivRhs& rhs, double tan_alpha) {
  double rate = 0.0;
  for (int i = 0; i <= 16; ++i) rate = std::max(rate, rhs.decayRate(tan_alpha * i / 16.0));
  return rate > 0.0 ? 1.5 / rate : 1e300;
}

struct MarchOutcome {
  std::vector<CycleRecord> cycles;
  std::vector<double> amplitudes;  // cycles[k].amplitude, for the stationarity test
  AmplitudeWindows windows;        // the stationarity test's last verdict
  double residual = 1.0;
  double needed_step = 0.0;  // > 0: the march stopped because the force curve got too steep for h
  double needed_tan = 0.0;   // the |ẏ/U| that step was computed for
  bool converged = false, at_rest = false, finite = true;
  long steps = 0;
  double fail_time = 0.0;
  int fail_index = 0;
};

MarchOutcome march(const FivRhs& rhs, State& s, const LimitCycleSettings& set, double h, double tan_start,
                   RunContext* ctx) {
  MarchOutcome out;
  const FivModel& model = rhs.model();
  const double t_end = set.max_cycles * 2.0 * std::numbers::pi / model.omega_n;
  const double inverse_speed = rhs.point().speed > 0.0 ? 1.0 / rhs.point().speed : 0.0;
  const double floor = 1e-6 * model.side;
  double t = 0.0, last_up = -1.0, e_damper_up = 0.0, e_fluid_up = 0.0;
  double cur_max = -1e300, cur_min = 1e300, cur_tan = 0.0, tan_checked = tan_start;
  std::size_t next_window_test = 0;  // the stationarity test costs O(n): run it after every n/32-th cycle
  State prev;
  for (long step = 0; t < t_end; ++step) {
    prev = s;
    rhs.step(s, h);
    t += h;
    ++out.steps;
    if (!std::isfinite(s[0]) || !std::isfinite(s[1]) || !std::isfinite(s[2]) || !std::isfinite(s[3])) {
      out.finite = false;
      out.fail_time = t;
      out.fail_index = !std::isfinite(s[0]) ? 0 : !std::isfinite(s[1]) ? 1 : !std::isfinite(s[2]) ? 2 : 3;
      return out;
    }
    if ((step & 4095) == 0 && ctx) ctx->throwIfCancelled();
    cur_tan = std::max(cur_tan, std::abs(s[1]) * inverse_speed);
    // Steeper parts of C_y reached than the step was chosen for: stop and ask for a smaller step.
    if (cur_tan > tan_checked) {
      tan_checked = 1.2 * cur_tan;
      const double stable = stableStep(rhs, tan_checked);
      if (stable < h) {
        out.needed_step = stable;
        out.needed_tan = tan_checked;
        return out;
      }
    }
    // Peaks: velocity changes sign inside the step; y there from the Hermite interpolant.
    if ((prev[1] > 0.0) != (s[1] > 0.0)) {
      const double tau = prev[1] / (prev[1] - s[1]);
      const double y_peak = hermite(prev[0], prev[1], s[0], s[1], h, tau);
      cur_max = std::max(cur_max, y_peak);
      cur_min = std::min(cur_min, y_peak);
    }
    // Zero up-crossing closes a cycle.
    if (!(prev[0] < 0.0 && s[0] >= 0.0)) continue;
    // Crossing time, speed and works from cubic Hermite interpolants (O(h⁴), so that the per-cycle
    // values used by the convergence test are smooth in the cycle count, not noisy at O(h²)).
    State d_prev, d_cur;
    rhs.derivative(prev, d_prev);
    rhs.derivative(s, d_cur);
    auto at = [&](int i, double x) { return hermite(prev[i], d_prev[i], s[i], d_cur[i], h, x); };
    double tau = prev[0] / (prev[0] - s[0]);
    for (int newton = 0; newton < 3; ++newton) {
      const double slope = (at(0, std::min(1.0, tau + 1e-6)) - at(0, std::max(0.0, tau - 1e-6))) /
                           (std::min(1.0, tau + 1e-6) - std::max(0.0, tau - 1e-6));
      if (slope > 0.0) tau = std::clamp(tau - at(0, tau) / slope, 0.0, 1.0);
    }
    const double t_up = t - h + tau * h;
    const double e_damper = at(4, tau);
    const double e_fluid = at(5, tau);
    if (last_up >= 0.0 && cur_max > -1e300 && cur_min < 1e300) {
      CycleRecord c;
      c.period = t_up - last_up;
      c.y_max = cur_max;
      c.y_min = cur_min;
      c.amplitude = 0.5 * (cur_max - cur_min);
      c.energy_damper = e_damper - e_damper_up;
      c.energy_fluid = e_fluid - e_fluid_up;
      c.max_tan_alpha = cur_tan;
      c.crossing_speed = at(1, tau);
      out.cycles.push_back(c);
      out.amplitudes.push_back(c.amplitude);
    }
    last_up = t_up;
    e_damper_up = e_damper;
    e_fluid_up = e_fluid;
    cur_max = -1e300;
    cur_min = 1e300;
    cur_tan = 0.0;
    const std::size_t n = out.cycles.size();
    if (n < 3) continue;
    // Decayed to rest (only possible without the wake oscillator).
    if (out.cycles[n - 1].amplitude < set.rest_amplitude &&
        out.cycles[n - 1].amplitude < out.cycles[n - 2].amplitude) {
      out.at_rest = out.converged = true;
      out.residual = out.cycles[n - 1].amplitude / model.side;
      return out;
    }
    if (static_cast<int>(n) < set.min_cycles) continue;
    const CycleRecord& last = out.cycles[n - 1];
    out.residual = std::max({remainingDrift(out.cycles, floor, [](const CycleRecord& c) { return c.amplitude; }),
                             remainingDrift(out.cycles, 1e-300, [](const CycleRecord& c) { return c.crossing_speed; }),
                             energyImbalance(last, model.total_mass)});
    const double period_change = std::abs(out.cycles[n - 1].period / out.cycles[n - 2].period - 1.0);
    if (out.residual < set.tolerance && period_change < set.tolerance) {
      out.converged = true;
      return out;
    }
    // Not periodic (yet): a stationary response whose windowed mean amplitude is already as precise as the
    // tolerance asks needs no more cycles. A stationary one that is less precise runs on, so that its
    // windows grow and its mean sharpens.
    if (n < next_window_test) continue;
    next_window_test = n + std::max<std::size_t>(1, n / 32);
    out.windows = compareAmplitudeWindows(out.amplitudes, set.min_window);
    if (out.windows.stationary && out.windows.error() <= set.tolerance * out.windows.mean &&
        windowPowerImbalance(out.cycles, out.windows.first) <= set.tolerance)
      return out;
  }
  if (out.cycles.size() >= 3) out.windows = compareAmplitudeWindows(out.amplitudes, set.min_window);
  return out;
}

// Averages the last whole cycles into the reported response.
LimitCycle summarise(const MarchOutcome& m, const LimitCycleSettings& set, double h, const FivModel& model) {
  LimitCycle r;
  r.cycles = static_cast<int>(m.cycles.size());
  r.steps = m.steps;
  r.step = h;
  r.converged = m.converged;
  r.at_rest = m.at_rest;
  r.residual = m.residual;
  if (m.cycles.empty()) {
    // No oscillation at all within max_cycles periods: the body sits at rest.
    r.at_rest = r.converged = true;
    r.residual = 0.0;
    r.response = ResponseKind::AtRest;
    return r;
  }
  const bool stationary = !m.converged && m.windows.stationary;
  r.response = m.at_rest ? ResponseKind::AtRest
               : m.converged ? ResponseKind::Periodic
               : stationary  ? ResponseKind::Stationary
                             : ResponseKind::Drifting;
  // A stationary response is averaged over both windows: its mean per-cycle amplitude is the paper's A
  // (half peak-to-peak per cycle) of a response whose cycles differ; f and the powers over the same cycles.
  const std::size_t n = m.cycles.size();
  const std::size_t k = stationary ? n - m.windows.first
                                   : std::min<std::size_t>(n, static_cast<std::size_t>(set.average_cycles));
  double period = 0.0, amp = 0.0, amp2 = 0.0, e_d = 0.0, e_f = 0.0, a_lo = 1e300, a_hi = 0.0;
  r.y_max = -1e300;
  r.y_min = 1e300;
  for (std::size_t i = n - k; i < n; ++i) {
    const CycleRecord& c = m.cycles[i];
    period += c.period;
    amp += c.amplitude;
    amp2 += c.amplitude * c.amplitude;
    e_d += c.energy_damper;
    e_f += c.energy_fluid;
    a_lo = std::min(a_lo, c.amplitude);
    a_hi = std::max(a_hi, c.amplitude);
    r.y_max = std::max(r.y_max, c.y_max);
    r.y_min = std::min(r.y_min, c.y_min);
    r.max_tan_alpha = std::max(r.max_tan_alpha, c.max_tan_alpha);
  }
  r.frequency = static_cast<double>(k) / period;
  r.amplitude = m.at_rest ? 0.0 : amp / static_cast<double>(k);
  r.power_damper = e_d / period;
  r.power_fluid = e_f / period;
  const double mean = amp / static_cast<double>(k);
  r.amplitude_spread = m.at_rest ? 0.0 : std::sqrt(std::max(0.0, amp2 / static_cast<double>(k) - mean * mean));
  const double scale = std::max(r.amplitude, 1e-6 * model.side);
  if (stationary) {
    // The error of the mean amplitude: the two windows' means apart, or the batch means' standard error; that
    // of the powers: the windows' energy imbalance.
    r.residual = std::max(m.windows.error() / scale, windowPowerImbalance(m.cycles, m.windows.first));
  } else if (!m.converged && r.amplitude > 0.0) {
    // Still drifting: the drift estimate or the last cycles' spread, whichever is larger, is the error bar.
    r.residual = std::max(r.residual, 0.5 * (a_hi - a_lo) / scale);
  }
  return r;
}

void recordHistory(const FivRhs& rhs, State& s, double h, double duration, History& out, RunContext* ctx) {
  const long n = checkedCount(duration / h, kMaxStoredSamples, "parameters.numerics.steps_per_period", "recorded samples");
  out = History{};
  for (long i = 0; i <= n; ++i) {
    if (i > 0) rhs.step(s, h);
    if ((i & 4095) == 0 && ctx) ctx->throwIfCancelled();
    const FluidForce f = rhs.force(s);
    out.time.push_back(static_cast<double>(i) * h);
    out.displacement.push_back(s[0]);
    out.velocity.push_back(s[1]);
    out.wake.push_back(s[2]);
    out.force_galloping.push_back(f.galloping);
    out.force_vortex.push_back(f.vortex);
  }
}

}  // namespace

AmplitudeWindows compareAmplitudeWindows(const std::vector<double>& amplitudes, int min_window) {
  AmplitudeWindows w;
  const std::size_t n = amplitudes.size();
  const std::size_t window = n / 4;
  if (window < static_cast<std::size_t>(std::max(4, min_window))) return w;  // 8 batches of at least one cycle
  w.window = window;
  w.first = n - 2 * window;
  // Mean and standard deviation of a_k over [begin, begin + window).
  auto stats = [&](std::size_t begin) {
    double sum = 0.0, sum2 = 0.0;
    for (std::size_t i = begin; i < begin + window; ++i) sum += amplitudes[i];
    const double mean = sum / static_cast<double>(window);
    for (std::size_t i = begin; i < begin + window; ++i) sum2 += (amplitudes[i] - mean) * (amplitudes[i] - mean);
    return std::pair{mean, std::sqrt(sum2 / static_cast<double>(window))};
  };
  const auto [m1, s1] = stats(w.first);
  const auto [m2, s2] = stats(w.first + window);
  const double pooled = std::sqrt(0.5 * (s1 * s1 + s2 * s2));
  w.mean = 0.5 * (m1 + m2);
  // Over both windows: the pooled within-window variance plus the part from the two means' difference.
  w.spread = std::sqrt(pooled * pooled + 0.25 * (m2 - m1) * (m2 - m1));
  w.change = std::abs(m2 - m1);
  w.stationary = w.change <= 0.5 * pooled && std::abs(s2 - s1) <= 0.5 * pooled;
  constexpr std::size_t kBatches = 8;
  const std::size_t batch = 2 * window / kBatches;
  std::array<double, kBatches> batch_means{};
  double grand = 0.0;
  for (std::size_t b = 0; b < kBatches; ++b) {
    double sum = 0.0;
    for (std::size_t i = n - (kBatches - b) * batch; i < n - (kBatches - b - 1) * batch; ++i) sum += amplitudes[i];
    batch_means[b] = sum / static_cast<double>(batch);
    grand += batch_means[b] / kBatches;
  }
  double var = 0.0;
  for (double b : batch_means) var += (b - grand) * (b - grand) / (kBatches - 1);
  w.standard_error = std::sqrt(var / kBatches);
  return w;
}

LimitCycle runToLimitCycle(const FivRhs& rhs, State& state, const LimitCycleSettings& settings, RunContext* context,
                           History* record, int record_cycles) {
  const FivModel& model = rhs.model();
  const OperatingPoint& op = rhs.point();
  double shortest = 2.0 * std::numbers::pi / model.omega_n;
  if (model.viv_on && op.wake_omega > 0.0) shortest = std::min(shortest, 2.0 * std::numbers::pi / op.wake_omega);
  double h = shortest / settings.steps_per_period;
  // Exactly at rest without a wake oscillator: rest is a solution, nothing to march.
  if (!model.viv_on && std::hypot(state[0], state[1] / model.omega_n) < settings.rest_amplitude) {
    LimitCycle r;
    r.at_rest = r.converged = true;
    r.response = ResponseKind::AtRest;
    r.step = h;
    r.frequency = model.f_n * std::sqrt(1.0 - model.damping_ratio * model.damping_ratio);
    if (record) recordHistory(rhs, state, h, record_cycles / model.f_n, *record, context);
    return r;
  }
  // Step also bounded by the steepest force-curve slope the continuation state's amplitude reaches.
  const double inverse_speed = op.speed > 0.0 ? 1.0 / op.speed : 0.0;
  double tan_start = 1.2 * std::hypot(state[0] * model.omega_n, state[1]) * inverse_speed;
  h = std::min(h, stableStep(rhs, tan_start));
  long steps = 0;
  for (int attempt = 0, refinements = 0;; ++attempt, h *= 0.5) {
    State s = state;
    s[4] = s[5] = 0.0;
    MarchOutcome m = march(rhs, s, settings, h, tan_start, context);
    steps += m.steps;
    if (m.needed_step > 0.0 && refinements < 20) {
      // Restart from the input state with the step the steeper curve needs (not counted as a failure).
      ++refinements;
      --attempt;
      h = 2.0 * m.needed_step;  // halved by the loop increment
      tan_start = m.needed_tan;
      continue;
    }
    if (m.finite) {
      LimitCycle r = summarise(m, settings, h, model);
      r.steps = steps;
      state = s;
      if (record) {
        const double period = r.frequency > 0.0 ? 1.0 / r.frequency : 2.0 * std::numbers::pi / model.omega_n;
        recordHistory(rhs, state, h, record_cycles * period, *record, context);
      }
      return r;
    }
    if (attempt == 3) {
      static const char* names[] = {"displacement y", "velocity dy/dt", "wake variable q", "wake rate dq/dt"};
      std::ostringstream detail;
      detail << "became non-finite at U = " << op.speed << " m/s, h* = " << op.submergence_ratio
             << " even with the RK4 step halved 3 times (h = " << h << " s); the force curve is probably too "
             << "steep for explicit integration: raise numerics.steps_per_period";
      throw SolverError(names[m.fail_index], m.fail_time, m.steps, detail.str());
    }
  }
}

}  // namespace maris::fiv
