// Parameters of the "fiv" scene: an elastically mounted square cylinder (1 DOF, cross-flow) under a
// free surface, driven by quasi-steady galloping and a wake oscillator (VIV). SI units throughout;
// the default member initialisers are the one source of defaults. Source of every coefficient is
// given in its schema description (fiv_parameters.cpp) and in docs/fiv.md.
//
// Defaults reproduce the set-up of Zhang, Song, Li, Su & Ding (square cylinder near a free surface,
// 2D URANS): D = 0.09 m, damping ratio 0.1, c ≈ 30 N·s/m. Mass, stiffness and length are not in the
// paper text; the defaults (m + m_a = 47.7 kg, k = 471 N/m, L = 1 m, f_n,water = 0.50 Hz) are placeholders:
// f_n,water ≈ 0.5 Hz from its galloping frequencies (0.49–0.54 Hz at 2.2 m/s), m_t = c/(2ξω_n), k = m_t ω_n².
#pragma once

#include <string>
#include <vector>

#include "core/schema_binder.hpp"

namespace maris::fiv {

// One row of a user-tabulated transverse-force curve C_y(α); α > 0 means the body moves in +y.
struct ForceCurvePoint {
  double angle_deg = 0.0;  // [deg] induced angle of attack α = atan(ẏ/U)
  double c_y = 0.0;        // [-] transverse force coefficient on ½ρU²DL, positive along +y
};

struct FivParameters {
  // structure
  double side = 0.09;                     // [m] side D of the square section
  double length = 1.0;                    // [m] span L
  double mass = 38.1;                     // [kg] oscillating mass without added mass
  double added_mass_coefficient = 1.19;   // [-] m_a = C_a ρ D² L (Blevins, square, flow normal to a face)
  double stiffness = 471.0;               // [N/m] spring stiffness k
  std::string damping_input = "ratio";    // "ratio": c = 2ξ√(k m_t); "coefficient": c given
  double damping_ratio = 0.1;             // [-] ξ
  double damping_coefficient = 30.0;      // [N·s/m] c_total (generator + transmission)
  // fluid
  double density = 998.2;                 // [kg/m³] ρ
  double kinematic_viscosity = 1.118e-6;  // [m²/s] ν (reproduces the paper's Re/U pairs with D = 0.09 m)
  double gravity = 9.81;                  // [m/s²] g, for the depth Froude number only
  // model switches
  std::string forcing = "combined";       // "galloping", "viv" or "combined"
  // galloping: quasi-steady C_y(tan α)
  std::string galloping_curve = "parkinson";  // "parkinson", "cubic" or "table"
  double parkinson_a1 = 2.69;             // [-] Parkinson & Smith (1964) square, smooth flow
  double parkinson_a3 = 168.0;            // [-]
  double parkinson_a5 = 6270.0;           // [-]
  double parkinson_a7 = 59900.0;          // [-]
  double cubic_a1 = 2.3;                  // [-] Barrero-Gil, Alonso & Sanz-Andrés (2010) square
  double cubic_a3 = -18.0;                // [-] C_y = a1 tanα + a3 tan³α
  double polynomial_tan_max = 0.35;       // [-] |tan α| beyond which a polynomial continues along its tangent
  std::vector<ForceCurvePoint> force_table = {
      {0, 0.0},      {2, 0.0871},  {4, 0.1407},  {6, 0.1596},  {8, 0.1906},
      {10, 0.3046},  {12, 0.5046}, {14, 0.5202}, {16, -0.5825}, {18, -5.0837}};
  double force_scale = 1.0;               // [-] calibration knob: multiplies C_y
  double angle_scale = 1.0;               // [-] calibration knob: C_y(t) -> s·C_y(t/s), keeps dC_y/dα at 0
  // VIV: Facchinetti, de Langre & Biolley (2004) wake oscillator
  double strouhal = 0.13;                 // [-] St of a square (Okajima 1982, quoted by the paper)
  double wake_lift_amplitude = 1.0;       // [-] C_L0, lift amplitude of the fixed section
  double wake_epsilon = 0.3;              // [-] ε, van der Pol parameter (Facchinetti 2004)
  double wake_coupling = 12.0;            // [-] A, acceleration coupling (Facchinetti 2004)
  // free surface: κ(h*) = 1 − a exp(−b (h* − ½)) on galloping (a_g) and VIV (a_v) forcing
  double surface_gallop_deficit = 0.22;   // [-] a_g
  double surface_viv_deficit = 0.22;      // [-] a_v
  double surface_decay = 0.75;            // [-] b
  std::vector<double> submergence_ratios = {1.11, 2.22, 3.33, 5.56};  // [-] h* = h/D (h to the centre)
  bool include_deep = true;               // also sweep h* = ∞ (no free surface, κ = 1)
  // sweep
  double speed_min = 0.2;                 // [m/s]
  double speed_max = 2.5;                 // [m/s]
  int speed_count = 50;                   // [-]
  bool sweep_down = true;                 // also sweep back down (continuation shows hysteresis)
  bool up_from_rest = false;              // every up-sweep speed starts from the seed (independent runs)
  double onset_amplitude_ratio = 1.0;     // [-] A/D above which the up-sweep counts as galloping
  // numerics
  int steps_per_period = 40;              // [-] RK4 steps per shortest period (structure or shedding)
  double convergence_tolerance = 1e-3;    // [-] relative amplitude change per cycle counted as converged
  int max_cycles = 150;                   // [-] structural periods simulated at most per speed
  double initial_amplitude_ratio = 0.05;  // [-] A/D of the seed perturbation
  // detail point: time history, spectrum, animation
  double detail_speed = 2.2;              // [m/s]
  double detail_submergence = 5.56;       // [-] h*; ignored when detail_deep
  bool detail_deep = false;               // detail point without free surface
  int detail_cycles = 40;                 // [-] cycles recorded for history and spectrum
  int animation_frames = 48;              // [-]
  // calibration
  bool calibrate = false;                 // fit the free coefficients before sweeping
  std::string reference_file;             // CSV of reference points; "" = the paper's points (built in)
  std::string free_coefficients = "galloping.force_scale, galloping.angle_scale, viv.wake_lift_amplitude, "
                                  "free_surface.gallop_deficit";  // comma-separated parameter paths
  int calibration_iterations = 25;        // [-] Levenberg–Marquardt iterations at most
  // post-processing of imported series
  std::string analysis = "sweep";         // "sweep" or "post_process"
  std::string series_file;                // CSV with time, y and optionally ydot, lift [N]
  double series_flow_speed = 2.2;         // [m/s] U of the imported series
};

SchemaBinder<FivParameters> fivBinder();

// Cross-field checks: speed range order, table monotonicity, calibration names, files present.
std::vector<FieldError> checkFivParameters(const FivParameters& p);

// Paths of the coefficients calibration may fit, and access to them by path.
const std::vector<std::string>& calibratableCoefficients();
double* coefficientByPath(FivParameters& p, const std::string& path);  // nullptr if not calibratable
std::vector<std::string> splitCoefficientList(const std::string& list);

}  // namespace maris::fiv
