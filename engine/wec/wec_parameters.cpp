#include "wec/wec_parameters.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace maris::wec {

namespace {

SchemaBinder<FloatRow> floatRowBinder() {
  SchemaBinder<FloatRow> b;
  b.real("hinge_x", &FloatRow::hinge_x, "m", Range::closed(-1e4, 1e4), "Hinge position along x");
  b.real("arm_length", &FloatRow::arm_length, "m", Range{0.0, 500.0, true, false}, "Arm length L, hinge to float centre");
  b.real("arm_angle_deg", &FloatRow::arm_angle_deg, "deg", Range::closed(-180.0, 0.0),
         "Equilibrium arm angle from +x towards +z (-90: float straight below the hinge)");
  b.real("radius", &FloatRow::radius, "m", Range{0.0, 100.0, true, false}, "Hemisphere radius");
  b.real("mass", &FloatRow::mass, "kg", Range::positive(1e9), "Float mass");
  b.real("inertia_cg", &FloatRow::inertia_cg, "kg*m^2", Range::nonNegative(1e13), "Pitch inertia about the float centre");
  b.real("pto_damping", &FloatRow::pto_damping, "N*m*s/rad", Range::nonNegative(1e12), "Linear PTO damping");
  b.real("pto_stiffness", &FloatRow::pto_stiffness, "N*m/rad", Range::nonNegative(1e12), "PTO spring about the equilibrium angle");
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"arm_length", "Arm length L"},
      {"radius", "Float radius"},
      {"mass", "Float mass"},
      {"pto_damping", "PTO damping"},
      {"pto_stiffness", "PTO stiffness"},
  });
  return b;
}

}  // namespace

SchemaBinder<WecParameters> wecBinder() {
  using P = WecParameters;
  SchemaBinder<P> b;
  b.real("water.density", &P::density, "kg/m^3", Range::closed(900.0, 1100.0), "Water density");
  b.real("water.gravity", &P::gravity, "m/s^2", Range::closed(9.0, 10.5), "Gravitational acceleration");
  b.real("water.depth", &P::depth, "m", Range::positive(1e4), "Water depth (coefficients are deep-water; flagged where kh < pi)");
  b.choice("hydro.source", &P::hydro_source, {"hemisphere_hulme", "wamit_files", "nemoh_files"},
           "Hydrodynamic coefficients: Hulme's floating hemisphere, WAMIT .1/.3 files or Nemoh/Capytaine .tec files");
  b.dataPath("hydro.wamit_stem", &P::wamit_stem, "WAMIT files without extension (reads <stem>.1 and <stem>.3)");
  b.real("hydro.wamit_length_scale", &P::wamit_length_scale, "m", Range::positive(1e4), "WAMIT ULEN");
  b.dataPath("hydro.nemoh_directory", &P::nemoh_directory,
             "Folder with Nemoh (or Capytaine legacy-export) RadiationCoefficients.tec and ExcitationForce.tec");
  b.table("floats", &P::floats, floatRowBinder(), 1, 8, "Floats, each on its own arm and hinge");
  b.choice("waves.type", &P::wave_type, {"none", "regular", "irregular"}, "Incident waves");
  b.choice("waves.direction", &P::wave_direction, {"+x", "-x"}, "Direction of wave travel");
  b.real("waves.height", &P::wave_height, "m", Range::nonNegative(30.0), "Regular wave height H");
  b.real("waves.frequency", &P::wave_frequency, "rad/s", Range::closed(0.05, 10.0), "Regular wave frequency");
  b.real("waves.ramp_duration", &P::ramp_duration, "s", Range::nonNegative(1e4), "Half-cosine ramp of the excitation");
  b.choice("waves.spectrum", &P::spectrum, {"jonswap", "pierson_moskowitz"}, "Irregular wave spectrum");
  b.real("waves.significant_height", &P::significant_height, "m", Range::nonNegative(30.0), "Significant wave height Hs");
  b.real("waves.peak_period", &P::peak_period, "s", Range::closed(1.0, 30.0), "Peak period Tp");
  b.real("waves.peak_enhancement", &P::peak_enhancement, "-", Range::closed(1.0, 10.0), "JONSWAP gamma");
  b.integer("waves.seed", &P::seed, "-", Range::closed(0, 2147483647),
            "Seed of the irregular sea's phases (mt19937_64; the same seed gives the bitwise same sea on every platform)");
  b.integer("waves.component_count", &P::component_count, "-", Range::closed(1, 5000), "Irregular wave components");
  b.choice("waves.discretisation", &P::discretisation, {"random_frequency", "equal_energy"},
           "Irregular sea frequencies: random within equal-width bins, or at the centroids of equal-energy bins "
           "(neither repeats with a common period)");
  b.choice("time.formulation", &P::formulation, {"classical", "augmented", "both"},
           "Classical (one ODE per float) and/or augmented (x, z, theta with hinge multipliers)");
  b.choice("time.radiation", &P::radiation, {"state_space", "direct"}, "Radiation memory evaluation");
  b.choice("time.augmented_integrator", &P::augmented_integrator, {"newmark_two_loop", "rk4"},
           "Augmented formulation: the paper's explicit Newmark with Newton-Raphson on the constraints, or RK4");
  b.choice("time.constraint_control", &P::constraint_control, {"projection", "baumgarte"},
           "Augmented RK4: project onto the constraints each step, or Baumgarte stabilisation only");
  b.real("time.baumgarte_rate", &P::baumgarte_rate, "1/s", Range::closed(0.0, 1e3), "Baumgarte rate alpha");
  b.real("time.duration", &P::duration, "s", Range::positive(1e5), "Simulated time");
  b.real("time.time_step", &P::time_step, "s", Range{0.0, 1.0, true, false}, "Time step (RK4 or Newmark)");
  b.real("time.kernel_duration", &P::kernel_duration, "s", Range::closed(2.0, 300.0), "Radiation kernel length");
  b.real("time.initial_offset_deg", &P::initial_offset_deg, "deg", Range::closed(-45.0, 45.0), "Initial angle offset from equilibrium");
  b.integer("time.animation_frames", &P::animation_frames, "-", Range::closed(1, 2000), "3D view frames");
  b.real("frequency.omega_min", &P::omega_min, "rad/s", Range::closed(0.01, 20.0), "Lowest sweep frequency");
  b.real("frequency.omega_max", &P::omega_max, "rad/s", Range::closed(0.02, 20.0), "Highest sweep frequency");
  b.integer("frequency.count", &P::frequency_count, "-", Range::closed(2, 100000), "Sweep frequencies");
  b.realList("frequency.check_frequencies", &P::check_frequencies, "rad/s", Range::closed(0.1, 10.0), 0, 40,
             "Frequencies of time-domain RAO runs overlaid on the frequency-domain curve");
  b.real("frequency.check_wave_height", &P::check_wave_height, "m", Range::positive(10.0), "Wave height of the RAO runs");
  b.realList("power_matrix.hs", &P::power_hs, "m", Range::positive(30.0), 0, 50, "Significant heights");
  b.realList("power_matrix.tp", &P::power_tp, "s", Range::closed(1.0, 30.0), 0, 50, "Peak periods");
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"floats", "float"},
      {"water.density", "Water density"},
      {"water.depth", "Water depth"},
      {"waves.height", "Wave height H"},
      {"waves.frequency", "Wave frequency ω"},
      {"waves.significant_height", "Significant wave height H_s"},
      {"waves.peak_period", "Peak period T_p"},
      {"waves.peak_enhancement", "Peak enhancement γ"},
      {"time.duration", "Simulated time"},
      {"time.time_step", "Time step h"},
  });
  return b;
}

std::vector<std::string> upgradeWecParameters(Json& parameters) {
  std::vector<std::string> notes;
  if (!parameters.is_object()) return notes;
  auto waves = parameters.find("waves");
  if (waves != parameters.end() && waves->is_object() && !waves->contains("discretisation")) {
    (*waves)["discretisation"] = "random_frequency";
    notes.push_back("waves.discretisation = random_frequency added (new in the wec schema: the irregular sea is "
                    "core's synthesis, so a seed gives another sea than before; save the scenario to keep it)");
  }
  return notes;
}

std::vector<FieldError> checkWecParameters(const WecParameters& p) {
  std::vector<FieldError> errors;
  auto num = [](double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  };
  for (std::size_t i = 0; i < p.floats.size(); ++i) {
    const auto& f = p.floats[i];
    const std::string row = "floats[" + std::to_string(i) + "].";
    // The arm must reach beyond the float: hinge outside the hemisphere.
    if (f.arm_length <= f.radius)
      errors.push_back({row + "arm_length", num(f.arm_length), "must exceed the float radius " + num(f.radius) + " m"});
    const double theta = f.arm_angle_deg * std::numbers::pi / 180.0;
    const double k_theta = p.density * p.gravity * std::numbers::pi * f.radius * f.radius *
                               std::pow(f.arm_length * std::cos(theta), 2) + f.pto_stiffness;
    if (k_theta < 1e-9 * f.mass * p.gravity * f.arm_length)
      errors.push_back({row + "pto_stiffness", num(f.pto_stiffness),
                        "must be > 0 when the arm is vertical (arm_angle_deg = -90 gives no hydrostatic restoring)"});
    for (std::size_t j = 0; j < i; ++j)
      if (std::abs(p.floats[j].hinge_x + p.floats[j].arm_length * std::cos(p.floats[j].arm_angle_deg * std::numbers::pi / 180.0) -
                   f.hinge_x - f.arm_length * std::cos(theta)) < p.floats[j].radius + f.radius)
        errors.push_back({row + "hinge_x", num(f.hinge_x), "float overlaps float " + std::to_string(j)});
  }
  if (p.wave_type == "irregular" && !(p.significant_height > 0.0))
    errors.push_back({"waves.significant_height", num(p.significant_height),
                      "must be > 0 for waves.type = irregular (waves.type = none gives calm water)"});
  if (p.time_step * 10.0 > p.duration)
    errors.push_back({"time.time_step", num(p.time_step), "must be at most duration/10 = " + num(p.duration / 10)});
  if (p.omega_max <= p.omega_min)
    errors.push_back({"frequency.omega_max", num(p.omega_max), "must exceed frequency.omega_min = " + num(p.omega_min)});
  if (p.hydro_source == "wamit_files" && p.wamit_stem.empty())
    errors.push_back({"hydro.wamit_stem", "\"\"", "must name the WAMIT files when hydro.source = wamit_files"});
  if (p.hydro_source == "nemoh_files" && p.nemoh_directory.empty())
    errors.push_back({"hydro.nemoh_directory", "\"\"", "must name the Nemoh results folder when hydro.source = nemoh_files"});
  if (p.power_hs.empty() != p.power_tp.empty())
    errors.push_back({"power_matrix.tp", "", "power_matrix.hs and power_matrix.tp must be both empty or both given"});
  return errors;
}

}  // namespace maris::wec
