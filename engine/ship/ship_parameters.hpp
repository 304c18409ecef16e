// Parameters of the ship resistance scene: one flat struct in SI units (the single source of defaults),
// its schema binder and the cross-field checks. Conventions: see hull_form.hpp.
#pragma once

#include <string>
#include <vector>

#include "core/schema_binder.hpp"
#include "ship/hull_form.hpp"

namespace maris::ship {

struct ShipParameters {
  // Hull
  std::string hull_source = "wigley";  // wigley | parametric | series60 | kcs | offsets_file
  double length = 4.0;                 // [m] Lpp; built-in tables are scaled geometrically to it
  double beam = 0.4;                   // [m] B of the wigley/parametric hull
  double draft = 0.25;                 // [m] T of the wigley/parametric hull
  double waterline_exponent = 2.0;     // [-] p of the parametric hull (C_WP = C_P = p/(p+1))
  double section_exponent = 2.0;       // [-] q of the parametric hull (C_M = q/(q+1))
  std::string offsets_file;            // CSV path (hull_source = offsets_file)
  double offsets_length_pp = 1.0;      // [m] Lpp of the table in offsets_file as written (scaled to `length`)
  double wetted_surface = 0.0;         // [m²] S used for coefficients; 0: computed from the geometry
  // Speeds
  double froude_min = 0.1;             // [-] sweep start, Fn = U/√(g Lpp)
  double froude_max = 0.6;             // [-] sweep end
  int froude_count = 251;              // [-] sweep points
  double design_froude = 0.35;         // [-] speed of the scalars, the wave spectrum and the wave pattern
  // Water
  std::string water = "fresh";         // fresh | sea (salinity 35 g/kg)
  double temperature = 15.0;           // [°C] water temperature
  double gravity = 9.81;               // [m/s²]
  // Viscous resistance
  std::string form_factor_method = "input";  // input | holtrop | prohaska (fit to measured.file)
  double form_factor = 1.095;          // [-] 1 + k (used when form_factor_method = input)
  double correlation_allowance = 0.0;  // [-] C_A added to C_T
  double prohaska_froude_max = 0.2;    // [-] measured points with Fn ≤ this enter the Prohaska fit
  // Holtrop–Mennen comparison
  std::string holtrop_edition = "1984";  // 1984 (Holtrop's re-analysis) | 1982 (Holtrop & Mennen's original)
  std::string stern_shape = "normal";  // pram_gondola | v_shaped | normal | u_shaped (C_stern −25, −10, 0, 10)
  bool holtrop_correlation_allowance = false;  // include Holtrop's R_A (full-scale ships only)
  // The paper's corrections
  bool tangency_correction = false;    // boundary-layer tangency correction (eqs 9–11)
  bool wave_number_correction = false; // k̂0 = k0 [1 + 3.7 (s_FS/l_FS − 1)] (eq 12)
  bool corrected_prefactor = false;    // also use k̂0 in the k0² prefactor of eq 8
  double short_wave_cutoff = 0.0;      // [-] discard waves shorter than this fraction of Lpp (0: off)
  double trip_position = 0.05;         // [-] forced laminar→turbulent transition, fraction of L from the bow
  double fore_shoulder = 0.0;          // [-] l_FS of eq 12 as a fraction of Lpp aft of the FP (0: first maximum of Y(x,0))
  // Full-scale extrapolation at equal Fn (ITTC-1978 form-factor method, hull only)
  double ship_length = 0.0;            // [m] Lpp of the full-scale ship (0: no extrapolation)
  double ship_water_temperature = 15.0;  // [°C] sea water temperature of the ship
  // Numerics
  int stations = 257;                  // [-] grid stations along the hull (4m + 1)
  int waterlines = 51;                 // [-] grid waterlines (odd)
  double relative_tolerance = 1e-4;    // [-] target of the λ quadrature and tail per speed
  int threads = 0;                     // [-] sweep threads (0: all hardware threads)
  // Measurements
  std::string measured_file;           // optional CSV with columns froude, c_total (names row, units row);
                                       // "builtin:NAME" reads resources/data/ship/NAME
};

SchemaBinder<ShipParameters> shipSchemaBinder();
std::vector<FieldError> checkShipParameters(const ShipParameters& p);

// The hull form the parameters describe (reads the built-in table or the offsets file). Throws InputError.
HullForm buildHullForm(const ShipParameters& p);

// Measured points from `measured_file`: columns froude and c_total. Throws InputError naming the line.
struct MeasuredPoints {
  std::vector<double> froude, c_total;
};
MeasuredPoints readMeasuredPoints(const std::string& path);
// True when `path` names a built-in measured data set ("builtin:NAME") rather than a file.
bool isBuiltinMeasured(const std::string& path);

}  // namespace maris::ship
