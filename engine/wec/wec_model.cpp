#include "wec/wec_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "core/ocean_waves.hpp"
#include "core/wave_spectrum.hpp"
#include "wec/wec_nemoh.hpp"
#include "wec/wec_wamit.hpp"

namespace maris::wec {

namespace {
using std::numbers::pi;
// β of the scene's direction of travel s = ±1 (cos β = s exactly: cos π rounds to −1).
double heading(double direction) { return direction < 0.0 ? pi : 0.0; }
}  // namespace

WecModel buildWecModel(const WecParameters& p) {
  WecModel m;
  m.density = p.density;
  m.gravity = p.gravity;
  m.depth = p.depth;
  m.direction = p.wave_direction == "-x" ? -1.0 : 1.0;
  std::shared_ptr<const HydroDatabase> imported;
  if (p.hydro_source == "wamit_files") imported = readWamit(p.wamit_stem, p.density, p.gravity, p.wamit_length_scale);
  if (p.hydro_source == "nemoh_files") {
    const NemohImport nemoh = readNemoh(p.nemoh_directory);
    imported = nemoh.hydro;
    m.coupled = nemoh.coupled;
    m.a_inf_error_surge = nemoh.a_inf_spread_surge;
    m.a_inf_error_heave = nemoh.a_inf_spread_heave;
  }
  if (m.coupled && m.coupled->bodies() != static_cast<int>(p.floats.size()))
    throw InputError("floats", std::to_string(p.floats.size()) + " rows",
                     "the Nemoh files describe " + std::to_string(m.coupled->bodies()) +
                         " bodies: give one float per body, in body order");
  if (m.coupled && m.direction < 0.0)
    throw InputError("waves.direction", "\"-x\"", "multi-body Nemoh coefficients are read for heading 0 only: use +x");
  for (const auto& row : p.floats) {
    FloatModel f;
    f.arm_length = row.arm_length;
    f.theta0 = row.arm_angle_deg * pi / 180.0;
    f.hinge_x = row.hinge_x;
    f.hinge_z = -row.arm_length * std::sin(f.theta0);
    f.radius = row.radius;
    f.mass = row.mass;
    f.inertia_cg = row.inertia_cg;
    f.inertia_hinge = row.inertia_cg + row.mass * row.arm_length * row.arm_length;
    f.pto_damping = row.pto_damping;
    f.pto_stiffness = row.pto_stiffness;
    f.waterplane_area = pi * row.radius * row.radius;
    f.x_f0 = row.hinge_x + row.arm_length * std::cos(f.theta0);
    // Floats of equal radius share one coefficient database (and, below, one set of kernels).
    if (m.coupled) {
      f.hydro = m.coupled->floatView(static_cast<int>(m.floats.size()));
      f.excitation_positioned = true;
    } else if (imported) {
      f.hydro = imported;
    } else {
      for (const auto& other : m.floats)
        if (other.radius == f.radius) f.hydro = other.hydro;
      if (!f.hydro) f.hydro = std::make_shared<HemisphereHydro>(row.radius, p.density, p.gravity);
    }
    m.floats.push_back(std::move(f));
  }
  return m;
}

void buildRadiation(WecModel& model, double kernel_duration, double kernel_dt, const RunContext* context) {
  for (std::size_t i = 0; i < model.floats.size(); ++i) {
    auto& f = model.floats[i];
    const FloatModel* twin = nullptr;
    for (std::size_t j = 0; j < i; ++j)
      if (model.floats[j].hydro == f.hydro) twin = &model.floats[j];
    if (twin) {
      f.surge = twin->surge;
      f.heave = twin->heave;
      continue;
    }
    const auto& hydro = *f.hydro;
    const double w_max = hydro.maxFrequency();
    const double d_omega = std::min(0.01, w_max / 400.0);
    auto build = [&](ModeRadiation& mode, bool heave) {
      auto damping = [&](double w) { return heave ? hydro.at(w).heave.damping : hydro.at(w).surge.damping; };
      auto added = [&](double w) { return heave ? hydro.at(w).heave.added_mass : hydro.at(w).surge.added_mass; };
      mode.a_inf = heave ? hydro.addedMassInfinityHeave() : hydro.addedMassInfinitySurge();
      mode.kernel = computeKernel(damping, w_max, d_omega, kernel_duration, kernel_dt, context);
      mode.fit = fitModalKernel(mode.kernel);
      mode.quality = assessFit(mode.fit, damping, added, mode.a_inf, 0.3, std::min(3.0, w_max));
    };
    build(f.surge, false);
    build(f.heave, true);
  }
  buildCrossRadiation(model, kernel_duration, kernel_dt, context);
}

FloatExcitation excitationAt(const WecModel& model, const FloatModel& f, double omega) {
  const FloatHydro h = f.hydro->at(omega);
  const double s = model.direction;
  if (f.excitation_positioned) return {h.surge.excitation, h.heave.excitation};
  const Complex location = std::polar(1.0, -s * waveNumber(omega, model.gravity) * f.x_f0);
  return {s * h.surge.excitation * location, h.heave.excitation * location};
}

double waveNumber(double omega, double gravity) { return ocean::waveNumber(omega, ocean::kDeepWater, gravity); }

// ---------------------------------------------------------------------------------------------
double IncidentWaves::ramp(double t) const { return ocean::startRamp(t, ramp_duration); }

double IncidentWaves::elevation(double x, double t) const { return ramp(t) * field.elevation(x, 0.0, t); }

IncidentWaves makeRegularWave(double height, double omega, double ramp, double direction, double gravity) {
  IncidentWaves w;
  w.field = ocean::WaveField({{omega, 0.5 * height, 0.0}}, heading(direction), ocean::kDeepWater, gravity,
                             ocean::Stretching::None);
  w.ramp_duration = ramp;
  return w;
}

ocean::WaveSpectrum seaSpectrum(const std::string& kind, double hs, double tp, double gamma) {
  return kind == "jonswap" ? ocean::jonswap(hs, tp, gamma) : ocean::piersonMoskowitz(hs, tp);
}

std::vector<double> spectrumDensity(const std::string& kind, double hs, double tp, double gamma,
                                    const std::vector<double>& omega) {
  const ocean::WaveSpectrum spectrum = seaSpectrum(kind, hs, tp, gamma);
  std::vector<double> s(omega.size());
  for (std::size_t i = 0; i < omega.size(); ++i) s[i] = spectrum.density(omega[i]);
  return s;
}

IncidentWaves makeIrregularWave(const WecParameters& p, double direction) {
  const auto method = p.discretisation == "equal_energy" ? ocean::Discretisation::EqualEnergy
                                                         : ocean::Discretisation::RandomFrequency;
  IncidentWaves w;
  w.field = ocean::irregularSea(seaSpectrum(p.spectrum, p.significant_height, p.peak_period, p.peak_enhancement),
                                p.component_count, method, static_cast<std::uint64_t>(p.seed), heading(direction),
                                ocean::kDeepWater, p.gravity, ocean::Stretching::None);
  w.ramp_duration = p.ramp_duration;
  return w;
}

ExcitationSeries makeExcitation(const WecModel& model, const FloatModel& f, const IncidentWaves& waves) {
  ExcitationSeries e;
  for (const auto& c : waves.field.components()) {
    const FloatExcitation x = excitationAt(model, f, c.omega);
    const Complex a = std::polar(c.amplitude, -c.phase);  // â = a e^{−iφ} (IncidentWaves)
    e.omega.push_back(c.omega);
    e.surge.push_back(x.surge * a);
    e.heave.push_back(x.heave * a);
  }
  return e;
}

void ExcitationSeries::evaluate(double t, double ramp, double& f_surge, double& f_heave) const {
  double fx = 0.0, fz = 0.0;
  for (std::size_t i = 0; i < omega.size(); ++i) {
    const Complex e(std::cos(omega[i] * t), std::sin(omega[i] * t));
    fx += (surge[i] * e).real();
    fz += (heave[i] * e).real();
  }
  f_surge = ramp * fx;
  f_heave = ramp * fz;
}

}  // namespace maris::wec
