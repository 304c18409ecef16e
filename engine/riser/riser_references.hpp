// Closed-form and semi-analytical natural frequencies of a straight riser, shared by the scene's
// frequency sweeps, the tests and bench/ (tensioned-beam and torsion closed forms; paper Sect. 8.2-8.3).
#pragma once

#include <vector>

namespace maris::riser {

// Eq (66) of the paper, tensioned pinned-pinned beam with constant tension and no flow:
//   ω_k = (kπ/L) √(T/m* + (kπ/L)² EI/m*)            [rad/s]
// length L [m], tension T [N], mass_per_length m* [kg/m] (wall + contents + added mass), ei [N·m²].
double tensionedBeamFrequency(int k, double length, double tension, double mass_per_length, double ei);

// A straight vertical pipe conveying fluid, pinned at both ends, tension falling linearly from the top.
struct ConveyingPipe {
  double length = 0.0;                // [m] L
  double mass_per_length = 0.0;       // [kg/m] m: wall + contents + added mass
  double fluid_mass_per_length = 0.0; // [kg/m] M = ρ_f A_inn of the contents
  double ei = 0.0;                    // [N·m²] bending stiffness
  double top_tension = 0.0;           // [N] effective tension at the top, s = 0
  double weight_per_length = 0.0;     // [N/m] w: submerged weight, T(s) = top_tension − w s
  double flow_speed = 0.0;            // [m/s] u of the contents
};

// Lowest `count` natural frequencies [rad/s] of
//   m ẅ + 2 M u ẇ' − ((T(s) − M u²) w')' + EI w'''' = 0,  w = w'' = 0 at both ends
// (Païdoussis, Fluid-Structure Interactions vol. 1, ch. 3, with a gravity-varying tension) by Galerkin
// on sin(kπs/L), k = 1..modes: mass mL/2 on the diagonal, stiffness EI(kπ/L)⁴ L/2 δ + ∫(T(s) − Mu²)φ'_j φ'_k
// (closed form for linear T), gyroscopic (skew) 2Mu ∫φ_j φ'_k = 2Mu·2jk/(j² − k²) for j + k odd, solved as
// a first-order eigenproblem; frequencies are the positive imaginary parts (stable range: λ = ±iω).
// The error falls fast with `modes` (16 and 24 modes differ by < 3e-7 relative for the tests' pipes).
// Returns fewer than `count` values when the pipe has diverged (some λ real).
std::vector<double> conveyingPipeFrequencies(const ConveyingPipe& pipe, int modes, int count);

}  // namespace maris::riser
