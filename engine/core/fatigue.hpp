// Fatigue of welded steel under variable amplitude stress: rainflow cycle counting (ASTM E1049-85 (2017),
// §5.4.4, three-point method with half cycles, from a turning-point extraction), bilinear S–N curves
// (DNVGL-RP-C203, Fatigue design of offshore steel structures, Edition April 2016, Tables 2-1 and 2-2, or a
// user curve), thickness correction (DNVGL-RP-C203 §2.4.3) and Palmgren–Miner damage.
#pragma once

#include <string>
#include <vector>

namespace maris::fatigue {

// Peaks and valleys of a signal: the first and last samples, and every sample where the signal turns.
// Plateaus count once; samples that continue a rise or fall are dropped. Non-finite input throws.
std::vector<double> turningPoints(const std::vector<double>& signal);

struct Cycle {
  double range = 0.0;  // [signal unit] |peak − valley|
  double mean = 0.0;   // [signal unit] (peak + valley)/2
  double count = 0.0;  // 1 (closed cycle) or 0.5 (half cycle)
};

// Rainflow counting, ASTM E1049-85 §5.4.4: with X the latest range and Y the one before it, Y is counted
// when X ≥ Y, as one cycle (and its two points discarded) unless Y contains the starting point, in which
// case as a half cycle (and the starting point discarded); the ranges left at the end count as half cycles.
// Cycles are returned in the order they are counted.
std::vector<Cycle> rainflow(const std::vector<double>& signal);

// log10 N = log10 a_1 − m_1 log10(Δσ·f_t) for N ≤ N_transition, log10 a_2 − m_2 log10(Δσ·f_t) beyond
// (Δσ in MPa; f_t = (max(t, t_ref)/t_ref)^k the thickness factor). m_2 = 0: a single slope everywhere.
struct SnCurve {
  std::string name;
  double log_a1 = 0.0;               // [-] log10 of a_1 with Δσ in MPa
  double m1 = 3.0;                   // [-]
  double log_a2 = 0.0;               // [-]
  double m2 = 0.0;                   // [-] 0: single slope
  double transition_cycles = 0.0;    // [-] N where the slopes change (1e7 in air, 1e6 in seawater with CP)
  double thickness_exponent = 0.0;   // [-] k
  double reference_thickness = 25.0; // [mm] t_ref (25 mm for welded connections other than tubular joints)
  // Stress range at the slope change, 10^((log a_1 − log N_t)/m_1) [MPa]; 0 for a single slope.
  double transitionRange() const;
};

enum class SnEnvironment { Air, SeawaterCathodicProtection, SeawaterFreeCorrosion };

// The DNVGL-RP-C203 (2016) curve `name` (B1, B2, C, C1, C2, D, E, F, F1, F3, G, W1, W2, W3) in air (Table 2-1),
// in seawater with cathodic protection (Table 2-2) or in seawater for free corrosion (one slope, m = 3),
// with its thickness exponent k and t_ref = 25 mm.
// Throws std::invalid_argument naming the curve and listing the valid names.
SnCurve dnvCurve(const std::string& name, SnEnvironment environment);
std::vector<std::string> dnvCurveNames();
// The fatigue limit the tables list for each curve: the stress range at 10^7 cycles [MPa].
double dnvFatigueLimit(const std::string& name);

// Cycles to failure at stress range Δσ [MPa] for thickness t [mm] (≤ 0: no correction); ∞ for Δσ = 0.
double cyclesToFailure(const SnCurve& curve, double stress_range_mpa, double thickness_mm);
// Palmgren–Miner damage Σ n_i/N_i of cycles whose ranges are in Pa (converted to MPa here).
double minerDamage(const std::vector<Cycle>& cycles_pa, const SnCurve& curve, double thickness_mm);

}  // namespace maris::fatigue
