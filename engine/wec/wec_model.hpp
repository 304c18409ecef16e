// Hinged-float WEC: derived model (built once from validated parameters).
//
// Conventions of the wec scene:
//   * planar x–z frame, z up, origin on the still-water plane; waves travel along +x (or −x);
//   * θ is the arm angle from +x towards +z; the float centre is r_f = r_h + L(cos θ, sin θ) and lies
//     on the still-water plane at the equilibrium angle θ0, so the hinge height is z_h = −L sin θ0;
//   * moments about the hinge are positive when they increase θ: M = r_x F_z − r_z F_x (paper eq 9);
//   * the hinge reaction (F_h,x, F_h,z) is the force the arm's pin exerts ON THE STRUCTURE:
//     F_h = Q_hydro − m ü_f (paper eqs 14–15), Q_hydro = excitation + radiation + hydrostatic; the PTO acts
//     as a torque between arm and structure and is reported separately (M_PTO = −B θ̇ − k(θ − θ0), on the arm);
//   * complex amplitudes: e^{+iωt}, η(x, t) = Re{a e^{i(ωt − kx)}} (see wec_hydro.hpp);
//   * weight and still-water buoyancy cancel (water-ballasted float), hydrostatics are linear:
//     F_z,hs = −ρ g A_w u_z with u_z = z_f (paper eq 7);
//   * built-in hydrodynamics are deep-water and without float–float interaction (each float sees the incident
//     wave at its own position; depth only raises a flag where kh < π); multi-body Nemoh/Capytaine files add
//     the interaction (WecModel::coupled, wec_coupled.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/ocean_waves.hpp"
#include "wec/wec_coupled.hpp"
#include "wec/wec_hydro.hpp"
#include "wec/wec_parameters.hpp"
#include "wec/wec_radiation.hpp"

namespace maris::wec {

// Radiation memory of one mode: kernel, its modal fit and the fit's quality.
struct ModeRadiation {
  double a_inf = 0.0;        // [kg] A∞
  RadiationKernel kernel;    // K(t) on the kernel grid
  ModalKernel fit;           // state-space (Prony) approximation
  FitQuality quality;        // frequency-domain reconstruction error of the fit
};

struct FloatModel {
  double hinge_x = 0.0, hinge_z = 0.0;  // [m] r_h
  double arm_length = 0.0;              // [m] L
  double theta0 = 0.0;                  // [rad] equilibrium angle
  double radius = 0.0;                  // [m]
  double mass = 0.0;                    // [kg] m
  double inertia_cg = 0.0;              // [kg·m²]
  double inertia_hinge = 0.0;           // [kg·m²] I = I_cg + m L²
  double pto_damping = 0.0;             // [N·m·s/rad]
  double pto_stiffness = 0.0;           // [N·m/rad]
  double waterplane_area = 0.0;         // [m²] πa²
  double x_f0 = 0.0;                    // [m] float centre x at equilibrium
  std::shared_ptr<const HydroDatabase> hydro;
  bool excitation_positioned = false;   // true: hydro's excitation already holds the location phase (multi-body)
  ModeRadiation surge, heave;           // filled by buildRadiation
};

// Radiation between two different translational DoFs (multi-body coefficients): the force on DoF `row` from the
// motion of DoF `col`, DoF index 2·float + (0 surge, 1 heave).
struct CrossRadiation {
  int row = 0, col = 0;
  ModeRadiation mode;
};

struct WecModel {
  double density = 0.0, gravity = 0.0, depth = 0.0;
  double direction = 1.0;  // +1: waves travel along +x, −1: along −x
  // [kg] error bar of A∞ when it was recovered by Ogilvie from an imported table (Nemoh), 0 otherwise.
  double a_inf_error_surge = 0.0, a_inf_error_heave = 0.0;
  std::vector<FloatModel> floats;
  std::shared_ptr<const CoupledHydro> coupled;  // multi-body coefficients; null: floats do not interact
  std::vector<CrossRadiation> cross;  // off-diagonal radiation entries, filled by buildRadiation (coupled only)
};

// Derived geometry and hydrodynamics; radiation kernels are computed by buildRadiation (costly).
// Throws InputError if the WAMIT files cannot be read.
WecModel buildWecModel(const WecParameters& p);
// Kernels K(t) from B(ω) on [0, hydro max frequency], A∞ from the database, modal fits.
// Cancellable through `context` (if given).
void buildRadiation(WecModel& model, double kernel_duration, double kernel_dt, const RunContext* context = nullptr);

// Deep-water wave number k = ω²/g [1/m] (ocean::waveNumber with h = ∞).
double waveNumber(double omega, double gravity);

// Excitation per unit amplitude on float `f` at its equilibrium position for waves along `direction`:
// the surge force of waves travelling along −x is the mirror image (sign flip), and the location phase
// is e^{−i k s x_f}, s = direction.
struct FloatExcitation {
  Complex surge, heave;  // [N/m]
};
FloatExcitation excitationAt(const WecModel& model, const FloatModel& f, double omega);

// Incident waves: core's linear wave field (ocean::WaveField in deep water, travelling along +x, β = 0, or −x,
// β = π) started by the half-cosine ramp ocean::startRamp. Core writes a component as a cos(k x cos β − ωt + φ);
// in the scene's e^{+iωt} convention that is η = Re{â e^{i(ωt − s k x)}} with â = a e^{−iφ} (s = ±1).
struct IncidentWaves {
  ocean::WaveField field;      // no components: calm water
  double ramp_duration = 0.0;  // [s] T_r
  double ramp(double t) const;
  double elevation(double x, double t) const;  // [m] η(x, t), ramped
};
// A regular wave of height H [m] at ω [rad/s], crest at x = 0 at t = 0.
IncidentWaves makeRegularWave(double height, double omega, double ramp, double direction, double gravity);
// Irregular sea from ocean::irregularSea: waves.spectrum over its band [0.5, 6]·ω_p, waves.component_count
// components placed by waves.discretisation, phases (and random_frequency's frequencies) from mt19937_64(waves.seed)
// through core's portable uniform draw, so a seed gives the bitwise same sea on every platform.
IncidentWaves makeIrregularWave(const WecParameters& p, double direction);
// The scene's sea spectrum (waves.spectrum, Hs, Tp, γ): core/wave_spectrum's JONSWAP (σ = 0.07/0.09) or
// Pierson–Moskowitz, m0 = Hs²/16 over the whole frequency axis. Requires Hs > 0.
ocean::WaveSpectrum seaSpectrum(const std::string& kind, double hs, double tp, double gamma);
// One-sided spectrum S(ω) [m²·s/rad] of seaSpectrum on a grid.
std::vector<double> spectrumDensity(const std::string& kind, double hs, double tp, double gamma,
                                    const std::vector<double>& omega);

// Excitation force time history on one float for a wave field: precomputed complex coefficients.
struct ExcitationSeries {
  std::vector<double> omega;
  std::vector<Complex> surge, heave;  // [N] per component, X̂·â, â = a e^{−iφ}
  void evaluate(double t, double ramp, double& f_surge, double& f_heave) const;
};
ExcitationSeries makeExcitation(const WecModel& model, const FloatModel& f, const IncidentWaves& waves);

}  // namespace maris::wec
