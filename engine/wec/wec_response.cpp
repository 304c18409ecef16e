#include "wec/wec_response.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/checked_count.hpp"

#include "wec/wec_frequency.hpp"

namespace maris::wec {

double settlingTime(const WecModel& model) {
  double slowest = 1e300;
  for (const auto& f : model.floats) {
    const double wn = naturalFrequency(model, f);
    const FrequencyResponse r = solveFrequency(model, f, wn > 0.0 ? wn : 0.5);
    slowest = std::min(slowest, (f.pto_damping + r.damping) / (2.0 * r.inertia));
  }
  return std::clamp(7.0 / slowest, 20.0, 600.0);
}

SteadyResponse steadyResponse(const WecModel& model, double omega, double height, double ramp,
                              const TimeDomainOptions& base, int periods, RunContext* context) {
  const double period = 2.0 * std::numbers::pi / omega;
  TimeDomainOptions o = base;
  o.time_step = period / std::ceil(period / base.time_step);
  const double settle = ramp + settlingTime(model);
  o.duration = (std::ceil(settle / period) + periods) * period;
  o.output_stride = 1;
  o.initial_offset = 0.0;
  const IncidentWaves waves = makeRegularWave(height, omega, ramp, model.direction, model.gravity);
  const TimeDomainResult td = simulateTimeDomain(model, waves, o, context);

  SteadyResponse s;
  s.omega = omega;
  s.time_step = o.time_step;
  s.duration = o.duration;
  s.max_position_drift = td.max_position_drift;
  const double a = 0.5 * height;
  const double window = periods * period;
  const auto per = static_cast<std::size_t>(checkedCount(std::round(window / o.time_step), kMaxStoredSamples,
                                                         "parameters.time.time_step", "samples per analysis window"));
  if (per + 1 > td.time.size())
    throw InputError("parameters.time.duration", "", "is shorter than the analysis window of the response");
  const std::size_t last = td.time.size() - 1, first = last - per;
  for (std::size_t i = 0; i < model.floats.size(); ++i) {
    const auto& h = td.floats[i];
    std::vector<double> dtheta(h.theta.size());
    for (std::size_t k = 0; k < dtheta.size(); ++k) dtheta[k] = h.theta[k] - model.floats[i].theta0;
    s.pitch.push_back(harmonicAmplitude(td.time, dtheta, omega, periods) / a);
    s.hinge_fx.push_back(harmonicAmplitude(td.time, h.hinge_fx, omega, periods) / a);
    s.hinge_fz.push_back(harmonicAmplitude(td.time, h.hinge_fz, omega, periods) / a);
    // Mean powers from the cumulative works over the whole-period window.
    s.pto_power.push_back((h.pto_energy[last] - h.pto_energy[first]) / window);
    s.excitation_power.push_back((h.excitation_work[last] - h.excitation_work[first]) / window);
    s.radiated_power.push_back((h.radiation_work[last] - h.radiation_work[first]) / window);
  }
  return s;
}

}  // namespace maris::wec
