#include "wec/wec_time.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "core/checked_count.hpp"
#include "core/errors.hpp"
#include "core/ode.hpp"
#include "wec/wec_dynamics.hpp"
#include "wec/wec_frequency.hpp"
#include "core/text_format.hpp"

namespace maris::wec {

HistoryRecorder::HistoryRecorder(TimeDomainResult& r, std::size_t floats)
    : r_(r), e_pto_(floats, 0.0), w_exc_(floats, 0.0), w_rad_(floats, 0.0), prev_(floats) {}

void HistoryRecorder::accumulate(const std::vector<FloatLoads>& loads, double h) {
  for (std::size_t i = 0; i < loads.size(); ++i) {
    e_pto_[i] += 0.5 * h * (prev_[i].p_pto + loads[i].p_pto);
    w_exc_[i] += 0.5 * h * (prev_[i].p_exc + loads[i].p_exc);
    w_rad_[i] += 0.5 * h * (prev_[i].p_rad + loads[i].p_rad);
  }
  prev_ = loads;
}

void HistoryRecorder::record(double t, double eta, const std::vector<FloatLoads>& loads) {
  r_.time.push_back(t);
  r_.wave_at_origin.push_back(eta);
  for (std::size_t i = 0; i < loads.size(); ++i) {
    auto& hst = r_.floats[i];
    const auto& l = loads[i];
    hst.theta.push_back(l.theta);
    hst.theta_dt.push_back(l.theta_dt);
    hst.theta_dtdt.push_back(l.theta_dtdt);
    hst.hinge_fx.push_back(l.fx);
    hst.hinge_fz.push_back(l.fz);
    hst.moment_y.push_back(l.moment);
    hst.pto_power.push_back(l.p_pto);
    hst.pto_energy.push_back(e_pto_[i]);
    hst.excitation_work.push_back(w_exc_[i]);
    hst.radiation_work.push_back(w_rad_[i]);
    hst.mechanical_energy.push_back(l.energy);
  }
}

double rk4StabilityStep(const WecModel& model, const TimeDomainOptions& options) {
  double fastest = 0.0;  // [1/s] largest |λ| scaled to the RK4 real-axis limit 2.785
  for (const auto& f : model.floats) {
    if (options.state_space)
      for (const auto* fit : {&f.surge.fit, &f.heave.fit})
        for (const auto& m : fit->modes) fastest = std::max(fastest, std::abs(m.pole) / 2.785);
    fastest = std::max(fastest, naturalFrequency(model, f) / 2.828);
  }
  if (options.state_space)
    for (const auto& c : model.cross)
      for (const auto& m : c.mode.fit.modes) fastest = std::max(fastest, std::abs(m.pole) / 2.785);
  if (options.augmented) fastest = std::max(fastest, options.baumgarte_rate / 2.785);
  return fastest > 0.0 ? 1.0 / fastest : 1.0;
}

TimeDomainResult simulateTimeDomain(const WecModel& model, const IncidentWaves& waves, const TimeDomainOptions& o,
                                    RunContext* context, const TimeDomainObserver& observe) {
  if (o.augmented && o.newmark) return simulateNewmark(model, waves, o, context, observe);
  WecDynamics sim(model, waves, o);
  const std::size_t nf = model.floats.size();
  TimeDomainResult r;
  r.floats.resize(nf);
  r.stability_step = rk4StabilityStep(model, o);
  r.method = std::string(o.augmented ? "augmented" : "classical") + ", RK4 h=" + numberText(o.time_step) +
             " s, radiation " + (o.state_space ? "state-space" : "direct convolution");
  const double h = o.time_step;
  const long n_steps = std::lround(o.duration / h);
  Eigen::VectorXd y = sim.initialState();
  std::vector<FloatLoads> loads(nf);
  HistoryRecorder recorder(r, nf);
  sim.advanceHistory(y);

  // The shared RK4 (core/ode.hpp). The step's start time gives the direct memory its position inside the
  // step; the evaluation at a step point (the first stage, FSAL) also fills the loads that are recorded.
  // The error estimate of θ [rad] compares the last stage (k4, at the step's end) with the end slope k5 (the
  // next step's first stage) on the θ components: h |k4 − k5| / 6, the shared estimator restricted to θ.
  double step_start = 0.0;
  std::vector<Eigen::Index> theta_index;
  for (const auto& f : sim.floats()) theta_index.push_back(f.offset + (o.augmented ? 2 : 0));
  Eigen::VectorXd k4_theta(static_cast<Eigen::Index>(nf));
  bool have_k4 = false;
  const OdeRhs rhs = [&](double t, const Eigen::VectorXd& state, Eigen::VectorXd& dy) {
    const double frac = std::clamp((t - step_start) / h, 0.0, 1.0);
    sim.rhs(t, frac, state, dy, frac == 0.0 ? &loads : nullptr);
    if (frac > 1.0 - 1e-9) {
      for (std::size_t i = 0; i < nf; ++i) k4_theta[static_cast<Eigen::Index>(i)] = dy[theta_index[i]];
      have_k4 = true;
    } else if (frac == 0.0 && have_k4) {
      double local = 0.0;
      for (std::size_t i = 0; i < nf; ++i)
        local = std::max(local, std::abs(k4_theta[static_cast<Eigen::Index>(i)] - dy[theta_index[i]]));
      r.error_estimate += h / 6.0 * local;
      have_k4 = false;
    }
  };
  OdeOptions ode;
  ode.t1 = h * static_cast<double>(n_steps);
  ode.step = h;
  ode.state_name = [&](Eigen::Index k) {
    std::string what = "state " + std::to_string(k);
    if (h > r.stability_step)
      what += " (time step above the estimated RK4 stability limit " + numberText(r.stability_step) + " s)";
    return what;
  };
  // After each step: projection onto the hinge constraints (augmented), then the velocity history (direct).
  ode.after_step = [&](double t, Eigen::VectorXd& state) {
    if (o.augmented) sim.project(state, r.max_position_drift, r.max_velocity_drift);
    if (state.allFinite()) sim.advanceHistory(state);
    step_start = t;
  };
  long n = 0;
  const OdeObserver record = [&](double t, const Eigen::VectorXd&) {
    recorder.accumulate(loads, n > 0 ? h : 0.0);
    if (n % o.output_stride == 0 || n == n_steps) {
      recorder.record(t, waves.elevation(0.0, t), loads);
      if (observe && context && n < n_steps && context->wantsPartialResults()) observe(r);
    }
    ++n;
  };
  Eigen::VectorXd initial_slope(sim.size());
  sim.rhs(0.0, 0.0, y, initial_slope, &loads);  // the loads at t = 0 (the observer sees t0 before any stage)
  RunContext quiet;
  const OdeStats stats = integrateRk4(rhs, y, ode, context ? *context : quiet, record);
  r.steps = stats.steps;
  r.relative_error_estimate = stats.error_estimate;
  r.rhs_evaluations = sim.evaluations();
  return r;
}

Complex harmonicAmplitude(const std::vector<double>& t, const std::vector<double>& s, double omega, int periods) {
  const double period = 2.0 * std::numbers::pi / omega;
  const double dt = t[1] - t[0];
  const auto per_period = static_cast<std::size_t>(
      checkedCount(std::round(period / dt), kMaxStoredSamples, "parameters.time.time_step", "samples per wave period"));
  const std::size_t count = per_period * static_cast<std::size_t>(periods);
  const std::size_t start = t.size() - count;
  Complex sum(0.0, 0.0);
  for (std::size_t i = start; i < t.size(); ++i) sum += s[i] * std::polar(1.0, -omega * t[i]);
  return 2.0 * sum / static_cast<double>(count);
}

}  // namespace maris::wec
