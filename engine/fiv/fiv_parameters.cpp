#include "fiv/fiv_parameters.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/resources.hpp"

namespace maris::fiv {

namespace {

SchemaBinder<ForceCurvePoint> forceCurveRowBinder() {
  SchemaBinder<ForceCurvePoint> b;
  b.real("angle_deg", &ForceCurvePoint::angle_deg, "deg", Range::closed(0, 89), "Induced angle α = atan(ẏ/U)");
  b.real("c_y", &ForceCurvePoint::c_y, "-", Range::closed(-1e4, 1e4), "Transverse force coefficient on ½ρU²DL");
  return b;
}

using P = FivParameters;

void bindStructureAndFluid(SchemaBinder<P>& b) {
  b.real("structure.side", &P::side, "m", Range::positive(100), "Side D of the square section (paper: 0.09 m)");
  b.real("structure.length", &P::length, "m", Range::positive(1e4),
         "Span L (not in the paper text; placeholder 1 m)");
  b.real("structure.mass", &P::mass, "kg", Range::positive(1e9),
         "Oscillating mass without added mass (placeholder: m + m_a = 47.7 kg gives f_n = 0.5 Hz)");
  b.real("structure.added_mass_coefficient", &P::added_mass_coefficient, "-", Range::closed(0, 10),
         "C_a in m_a = C_a ρ D² L; 1.19 = potential flow, square normal to a face (Blevins)");
  b.real("structure.stiffness", &P::stiffness, "N/m", Range::positive(1e12), "Spring stiffness k (placeholder)");
  b.choice("structure.damping_input", &P::damping_input, {"ratio", "coefficient"},
           "Which damping value is given: ratio ξ (c = 2ξ√(k m_t)) or coefficient c");
  b.real("structure.damping_ratio", &P::damping_ratio, "-", Range::closed(0, 0.95),
         "Total damping ratio ξ incl. generator (paper: 0.1)");
  b.real("structure.damping_coefficient", &P::damping_coefficient, "N*s/m", Range::nonNegative(1e9),
         "Total damping coefficient c (paper: 'about 30')");
  b.real("fluid.density", &P::density, "kg/m^3", Range::positive(1e5), "Water density ρ");
  b.real("fluid.kinematic_viscosity", &P::kinematic_viscosity, "m^2/s", Range::positive(1),
         "ν; 1.118e-6 reproduces the paper's Re/U = 8.05e4 s/m with D = 0.09 m");
  b.real("fluid.gravity", &P::gravity, "m/s^2", Range::positive(100), "g, for the depth Froude number U/√(gh)");
}

void bindForcing(SchemaBinder<P>& b) {
  b.choice("model.forcing", &P::forcing, {"galloping", "viv", "combined"},
           "Fluid force: quasi-steady galloping, wake oscillator, or their sum (Tamura & Shimada 1987)");
  b.choice("galloping.curve", &P::galloping_curve, {"parkinson", "cubic", "table"},
           "C_y(α) model: Parkinson–Smith 7th-order polynomial, cubic, or the table below");
  b.real("galloping.a1", &P::parkinson_a1, "-", Range::closed(-100, 100), "Parkinson & Smith (1964) A1, square");
  b.real("galloping.a3", &P::parkinson_a3, "-", Range::closed(-1e6, 1e6), "Parkinson & Smith (1964) A3");
  b.real("galloping.a5", &P::parkinson_a5, "-", Range::closed(-1e7, 1e7), "Parkinson & Smith (1964) A5");
  b.real("galloping.a7", &P::parkinson_a7, "-", Range::closed(-1e8, 1e8), "Parkinson & Smith (1964) A7");
  b.real("galloping.cubic_a1", &P::cubic_a1, "-", Range::closed(-100, 100),
         "Cubic a1 (Barrero-Gil, Alonso & Sanz-Andrés 2010, square)");
  b.real("galloping.cubic_a3", &P::cubic_a3, "-", Range::closed(-1e6, 1e6), "Cubic a3 (same source)");
  b.real("galloping.polynomial_tan_max", &P::polynomial_tan_max, "-", Range::closed(0.05, 2),
         "|tan α| beyond which a polynomial C_y continues along its tangent (the fits are valid to ≈0.27)");
  SchemaBinder<ForceCurvePoint> row = forceCurveRowBinder();
  b.table("galloping.force_table", &P::force_table, row, 2, 500,
          "User C_y(α), α ascending from 0 (odd symmetry assumed; held constant beyond the last row); "
          "default samples Parkinson's polynomial");
  b.real("galloping.force_scale", &P::force_scale, "-", Range::closed(0, 10),
         "Calibration knob: multiplies C_y (1 = published curve)");
  b.real("galloping.angle_scale", &P::angle_scale, "-", Range::closed(0.2, 5),
         "Calibration knob: C_y(t) -> s·C_y(t/s), stretches the curve in angle keeping its initial slope");
  b.real("viv.strouhal", &P::strouhal, "-", Range::open(0, 1), "Strouhal number; 0.13 for a square (Okajima 1982)");
  b.real("viv.wake_lift_amplitude", &P::wake_lift_amplitude, "-", Range::closed(0, 10),
         "C_L0 (Facchinetti 2004: 0.3 circular; square fixed-body C_L,rms ≈ 1.0–1.3)");
  b.real("viv.wake_epsilon", &P::wake_epsilon, "-", Range::positive(10), "ε (Facchinetti 2004: 0.3)");
  b.real("viv.wake_coupling", &P::wake_coupling, "-", Range::closed(0, 100), "A (Facchinetti 2004: 12)");
}

void bindSurfaceSweepNumerics(SchemaBinder<P>& b) {
  b.real("free_surface.gallop_deficit", &P::surface_gallop_deficit, "-", Range::closed(0, 0.99),
         "a_g in κ_g = 1 − a_g exp(−b(h* − ½)) (fitted to the paper's power ratios; ours, not published)");
  b.real("free_surface.viv_deficit", &P::surface_viv_deficit, "-", Range::closed(0, 0.99),
         "a_v in κ_v = 1 − a_v exp(−b(h* − ½))");
  b.real("free_surface.decay", &P::surface_decay, "-", Range::positive(20), "b, decay of the deficit with h*");
  b.realList("free_surface.submergence_ratios", &P::submergence_ratios, "-", Range::closed(0.5, 1000), 0, 12,
             "h* = h/D values to sweep (h from the free surface to the cylinder centre)");
  b.boolean("free_surface.include_deep", &P::include_deep, "Also sweep h* = ∞ (single phase, κ = 1)");
  b.real("sweep.speed_min", &P::speed_min, "m/s", Range::nonNegative(100), "Lowest current speed");
  b.real("sweep.speed_max", &P::speed_max, "m/s", Range::positive(100), "Highest current speed");
  b.integer("sweep.speed_count", &P::speed_count, "-", Range::closed(1, 2000), "Number of speeds");
  b.boolean("sweep.sweep_down", &P::sweep_down, "Also sweep down from the top speed (hysteresis)");
  b.boolean("sweep.up_from_rest", &P::up_from_rest,
            "Start every up-sweep speed from the seed, like independent CFD runs, instead of continuing");
  b.real("sweep.onset_amplitude_ratio", &P::onset_amplitude_ratio, "-", Range::positive(100),
         "A/D from which the up-sweep response counts as galloping (onset detection)");
  b.integer("numerics.steps_per_period", &P::steps_per_period, "-", Range::closed(8, 2000),
            "RK4 steps per shortest period (structure or vortex shedding)");
  b.real("numerics.convergence_tolerance", &P::convergence_tolerance, "-", Range::closed(1e-8, 0.5),
         "Limit cycle converged when the estimated remaining amplitude change is below this fraction");
  b.integer("numerics.max_cycles", &P::max_cycles, "-", Range::closed(10, 100000),
            "Structural periods simulated at most per speed");
  b.real("numerics.initial_amplitude_ratio", &P::initial_amplitude_ratio, "-", Range::positive(10),
         "A/D of the seed perturbation (also the floor when continuing from rest)");
}

void bindOutputCalibrationSeries(SchemaBinder<P>& b) {
  b.real("detail.speed", &P::detail_speed, "m/s", Range::nonNegative(100), "Speed of the detailed point");
  b.real("detail.submergence_ratio", &P::detail_submergence, "-", Range::closed(0.5, 1000), "h* of the detail point");
  b.boolean("detail.deep", &P::detail_deep, "Detail point without free surface (h* = ∞)");
  b.integer("detail.cycles", &P::detail_cycles, "-", Range::closed(4, 2000), "Cycles recorded for history/spectrum");
  b.integer("detail.animation_frames", &P::animation_frames, "-", Range::closed(1, 1000), "Frames of the 3D view");
  b.boolean("calibration.enabled", &P::calibrate, "Fit the free coefficients to reference points first");
  b.dataPath("calibration.reference_file", &P::reference_file,
             "CSV of reference points (flow_speed, submergence_ratio, amplitude, frequency, power + sigmas); "
             "empty = the paper's points");
  b.text("calibration.free_coefficients", &P::free_coefficients,
         "Comma-separated parameter paths to fit (see docs/fiv.md for the allowed ones)");
  b.integer("calibration.max_iterations", &P::calibration_iterations, "-", Range::closed(1, 500),
            "Levenberg–Marquardt iterations at most");
  b.choice("analysis.mode", &P::analysis, {"sweep", "post_process"},
           "Sweep the model over U and h*, or post-process an imported time series");
  b.dataPath("analysis.series_file", &P::series_file, "CSV with columns time [s], y [m], optional ydot [m/s], lift [N]");
  b.real("analysis.series_flow_speed", &P::series_flow_speed, "m/s", Range::positive(100),
         "Current speed of the imported series (for efficiency)");
}

}  // namespace

SchemaBinder<FivParameters> fivBinder() {
  SchemaBinder<P> b;
  bindStructureAndFluid(b);
  bindForcing(b);
  bindSurfaceSweepNumerics(b);
  bindOutputCalibrationSeries(b);
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"structure.side", "Side D"},
      {"structure.length", "Span L"},
      {"structure.mass", "Mass m"},
      {"structure.added_mass_coefficient", "Added-mass coefficient C_a"},
      {"structure.stiffness", "Stiffness k"},
      {"structure.damping_ratio", "Damping ratio ξ"},
      {"structure.damping_coefficient", "Damping coefficient c"},
      {"fluid.density", "Water density ρ"},
      {"galloping.force_scale", "Force scale"},
      {"galloping.angle_scale", "Angle scale"},
      {"viv.strouhal", "Strouhal number St"},
      {"sweep.speed_min", "Lowest speed"},
      {"sweep.speed_max", "Highest speed"},
      {"detail.speed", "Detail speed"},
      {"detail.submergence_ratio", "Detail submergence h*"},
  });
  return b;
}

const std::vector<std::string>& calibratableCoefficients() {
  static const std::vector<std::string> names = {
      "galloping.force_scale",    "galloping.angle_scale",        "galloping.a1",
      "galloping.cubic_a1",       "galloping.cubic_a3",           "viv.wake_lift_amplitude",
      "viv.wake_epsilon",         "viv.wake_coupling",            "viv.strouhal",
      "free_surface.gallop_deficit", "free_surface.viv_deficit", "free_surface.decay",
      "structure.stiffness",      "structure.added_mass_coefficient"};
  return names;
}

double* coefficientByPath(FivParameters& p, const std::string& path) {
  if (path == "galloping.force_scale") return &p.force_scale;
  if (path == "galloping.angle_scale") return &p.angle_scale;
  if (path == "galloping.a1") return &p.parkinson_a1;
  if (path == "galloping.cubic_a1") return &p.cubic_a1;
  if (path == "galloping.cubic_a3") return &p.cubic_a3;
  if (path == "viv.wake_lift_amplitude") return &p.wake_lift_amplitude;
  if (path == "viv.wake_epsilon") return &p.wake_epsilon;
  if (path == "viv.wake_coupling") return &p.wake_coupling;
  if (path == "viv.strouhal") return &p.strouhal;
  if (path == "free_surface.gallop_deficit") return &p.surface_gallop_deficit;
  if (path == "free_surface.viv_deficit") return &p.surface_viv_deficit;
  if (path == "free_surface.decay") return &p.surface_decay;
  if (path == "structure.stiffness") return &p.stiffness;
  if (path == "structure.added_mass_coefficient") return &p.added_mass_coefficient;
  return nullptr;
}

std::vector<std::string> splitCoefficientList(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto first = item.find_first_not_of(" \t");
    const auto last = item.find_last_not_of(" \t");
    if (first != std::string::npos) out.push_back(item.substr(first, last - first + 1));
  }
  return out;
}

std::vector<FieldError> checkFivParameters(const FivParameters& p) {
  std::vector<FieldError> errors;
  auto num = [](double v) { std::ostringstream s; s << v; return s.str(); };
  if (p.speed_max <= p.speed_min && p.speed_count > 1)
    errors.push_back({"sweep.speed_max", num(p.speed_max),
                      "must exceed sweep.speed_min = " + num(p.speed_min) + " when sweep.speed_count > 1"});
  for (std::size_t i = 0; i < p.force_table.size(); ++i) {
    if (i == 0 && p.force_table[0].angle_deg != 0.0)
      errors.push_back({"galloping.force_table[0].angle_deg", num(p.force_table[0].angle_deg),
                        "the first row must be at α = 0 (C_y is taken odd in α)"});
    if (i > 0 && p.force_table[i].angle_deg <= p.force_table[i - 1].angle_deg)
      errors.push_back({"galloping.force_table[" + std::to_string(i) + "].angle_deg",
                        num(p.force_table[i].angle_deg), "angles must increase strictly down the table"});
  }
  if (p.submergence_ratios.empty() && !p.include_deep)
    errors.push_back({"free_surface.submergence_ratios", "[]",
                      "give at least one h* or set free_surface.include_deep = true"});
  if (p.calibrate) {
    const auto names = splitCoefficientList(p.free_coefficients);
    std::string allowed;
    for (const auto& c : calibratableCoefficients()) allowed += (allowed.empty() ? "" : ", ") + c;
    if (names.empty())
      errors.push_back({"calibration.free_coefficients", "\"\"", "name at least one coefficient to fit"});
    for (const auto& n : names) {
      FivParameters copy = p;
      if (!coefficientByPath(copy, n))
        errors.push_back({"calibration.free_coefficients", "\"" + n + "\"",
                          "is not a calibratable coefficient (allowed: " + allowed + ")"});
    }
  }
  if (!p.reference_file.empty())
    if (auto problem = dataPathProblem(p.reference_file, "fiv"))
      errors.push_back({"calibration.reference_file", "\"" + p.reference_file + "\"", *problem});
  if (p.analysis == "post_process") {
    if (p.series_file.empty())
      errors.push_back({"analysis.series_file", "\"\"", "post_process needs a CSV file with time and y columns"});
    else if (auto problem = dataPathProblem(p.series_file, "fiv"))
      errors.push_back({"analysis.series_file", "\"" + p.series_file + "\"", *problem});
  }
  if (p.forcing != "galloping" && p.strouhal <= 0.0)
    errors.push_back({"viv.strouhal", num(p.strouhal), "must be > 0 when the wake oscillator is on"});
  return errors;
}

}  // namespace maris::fiv
