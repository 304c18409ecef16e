// Holtrop & Mennen's statistical resistance prediction: Holtrop & Mennen (1982), "An approximate power
// prediction method", Int. Shipbuilding Progress 29(335); wave resistance as re-analysed by Holtrop (1984),
// "A statistical re-analysis of resistance and propulsion data", ISP 31(363). Bare hull (no appendages):
//   R_T = (1 + k1) R_F + R_W + R_B + R_TR (+ R_A when the correlation allowance is wanted).
// The regression covers roughly 0.55 ≤ C_P ≤ 0.85, 3.9 ≤ L/B ≤ 14.9, 2.1 ≤ B/T ≤ 4.0 and Fn ≤ 0.5 for
// conventional ships; holtropRangeNotes() lists the inputs outside it.
#pragma once

#include <string>
#include <vector>

namespace maris::ship {

// Which edition of the regression: the original (Holtrop & Mennen 1982: form factor with c12, c13 and one
// wave-resistance formula with m2 = c15 C_P² e^{−0.1 Fn^−2} at all speeds) or the re-analysis (Holtrop
// 1984: form factor with c14, wave resistance with m4 and a separate high-speed formula).
enum class HoltropEdition { Original1982, Revised1984 };

struct HoltropHull {
  double length_wl = 0;          // [m] L, waterline length
  double beam = 0;               // [m] B
  double draft = 0;              // [m] T (even keel: T_F = T_A = T)
  double volume = 0;             // [m³] ∇
  double lcb_percent = 0;        // [% L] LCB forward of 0.5 L
  double midship_coefficient = 0;     // C_M
  double waterplane_coefficient = 0;  // C_WP
  double wetted_surface = 0;     // [m²] S (the hull's own, not Holtrop's estimate)
  double bulb_area = 0;          // [m²] A_BT, transverse bulb area at the FP
  double bulb_centre_height = 0; // [m] h_B, its centroid above the keel
  double transom_area = 0;       // [m²] A_T, immersed transom area at rest
  double stern_shape = 0;        // [-] C_stern: −25 pram with gondola, −10 V, 0 normal, +10 U with Hogner stern
  double prismatic() const { return volume / (midship_coefficient * beam * draft * length_wl); }
};

struct HoltropResistance {
  double form_factor = 0;      // [-] 1 + k1
  double friction = 0;         // [N] R_F (ITTC-57 on L_WL)
  double wave = 0;             // [N] R_W
  double bulb = 0;             // [N] R_B
  double transom = 0;          // [N] R_TR
  double correlation = 0;      // [N] R_A (0 unless requested)
  double total = 0;            // [N] R_T
};

// 1984: 1 + k1 = 0.93 + 0.487118 c14 (B/L)^1.06806 (T/L)^0.46106 (L/L_R)^0.121563 (L³/∇)^0.36486 (1 − C_P)^−0.604247.
// 1982: 1 + k1 = c13 [0.93 + c12 (B/L_R)^0.92497 (0.95 − C_P)^−0.521448 (1 − C_P + 0.0225 lcb)^0.6906].
double holtropFormFactor(const HoltropHull& hull, HoltropEdition edition = HoltropEdition::Revised1984);
// Holtrop's correlation allowance C_A (for full-scale ships; meaningless at model scale).
double holtropCorrelationAllowance(const HoltropHull& hull);
// Resistance components at speed U [m/s] in water of density ρ and viscosity ν.
HoltropResistance holtropMennen(const HoltropHull& hull, double speed, double density, double viscosity,
                                double gravity, bool with_correlation_allowance,
                                HoltropEdition edition = HoltropEdition::Revised1984);
// Human-readable notes on inputs outside the regression's range (empty when inside).
std::vector<std::string> holtropRangeNotes(const HoltropHull& hull);

}  // namespace maris::ship
