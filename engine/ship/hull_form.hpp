// Hull geometry of the ship scene: a hull form (mathematical or an offsets table with monotone cubic
// interpolation), its sampling on the uniform station × waterline grid that Michell's integral uses, and the
// main particulars computed from that grid.
//
// Conventions (whole scene): x [m] from the aft perpendicular (AP), positive forward; the forward
// perpendicular (FP) is at x = Lpp. y [m] to starboard, the half-breadth Y(x, z) ≥ 0 is the largest |y| of
// the hull at (x, z). z [m] from the design waterline, positive up, so the submerged hull has z ≤ 0.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "ship/hull_offsets.hpp"

namespace maris::ship {

// Y(x, z) sampled on x_i = x_aft + i·dx (i < nx), z_j = −j·dz (j < nz): stations × waterlines.
struct HullGrid {
  double x_aft = 0.0;          // [m] first station (aft end of the submerged body)
  double dx = 0.0;             // [m] station spacing
  double dz = 0.0;             // [m] waterline spacing
  Eigen::MatrixXd half_breadth;  // [m] nx × nz, Y(x_i, z_j) ≥ 0; written by sampleHull
  // [-] order p the Richardson grid-error estimate assumes, error ≈ |R(h) − R(2h)|/(2^p − 1): 2 for the
  // smooth mathematical hulls (observed ≈ 2 on the Wigley hull), 1 for offsets tables, whose interpolated
  // surface has kinks (keel lines, domes, table nodes) and converges pre-asymptotically on real hulls.
  double convergence_order = 2.0;
  int nx() const { return static_cast<int>(half_breadth.rows()); }
  int nz() const { return static_cast<int>(half_breadth.cols()); }
  double x(int i) const { return x_aft + i * dx; }
  double z(int j) const { return -j * dz; }
  double depth() const { return (nz() - 1) * dz; }  // [m] deepest waterline (the draft of the grid)
  // Every other station and waterline (needs nx and nz odd): the coarse grid of the Richardson error estimate.
  HullGrid coarsened() const;
  // The hull turned end for end about its mid-length (the fore–aft reversal of the property tests).
  HullGrid reversed() const;
};

// A hull form that can be sampled at any resolution.
struct HullForm {
  enum class Kind { Parametric, Offsets };
  Kind kind = Kind::Parametric;
  std::string name;
  double length_pp = 4.0;  // [m] length between perpendiculars (Froude and coefficient length)
  // Parametric family Y = (B/2)(1 − |2ξ/L|^p)(1 − |z/T|^q), ξ = x − L/2 (p = q = 2: the Wigley hull).
  double beam = 0.4;              // [m] B
  double draft = 0.25;            // [m] T
  double waterline_exponent = 2;  // [-] p: C_WP = C_P = p/(p+1)
  double section_exponent = 2;    // [-] q: C_M = q/(q+1)
  OffsetsTable offsets;           // Kind::Offsets: the table, already scaled
  bool isWigley() const { return kind == Kind::Parametric && waterline_exponent == 2.0 && section_exponent == 2.0; }
};

HullForm makeParametricHull(double length, double beam, double draft, double waterline_exponent = 2.0,
                            double section_exponent = 2.0);
// An offsets hull, geometrically scaled by `scale` (all lengths multiplied). `length_pp` is the table's Lpp.
HullForm makeOffsetsHull(std::string name, OffsetsTable table, double length_pp, double scale = 1.0);

// Samples Y on nx × nz nodes spanning the submerged body (x from its aft to its forward end, z from 0 to the
// deepest point). nx, nz ≥ 3 and odd (Filon–Simpson and the coarse grid need that).
HullGrid sampleHull(const HullForm& hull, int nx, int nz);

// Main particulars from a grid (Simpson in x and z; wetted surface from the triangulated grid surface).
// C_B, C_M use the moulded draft T and B_WL; h_B of the bulb is measured from the keel at T.
struct HullParticulars {
  double length_pp = 0;        // [m] Lpp (given)
  double length_wl = 0;        // [m] waterline length (extent of Y(x, 0) > 0)
  double beam_wl = 0;          // [m] 2 max Y(x, 0)
  double draft = 0;            // [m] T: deepest keel point in the middle half of Lpp (excludes domes, bulbs)
  double max_depth = 0;        // [m] deepest point of the whole hull below the waterline
  double volume = 0;           // [m³] ∇ = 2 ∬ Y dz dx
  double wetted_surface = 0;   // [m²] both sides, hull below the waterline
  double waterplane_area = 0;  // [m²] 2 ∫ Y(x, 0) dx
  double max_section_area = 0; // [m²] A_M = max_x 2 ∫ Y dz
  double lcb_from_ap = 0;      // [m] centre of buoyancy from the AP
  double lcb_percent = 0;      // [% Lpp] LCB forward of midship (x = Lpp/2), negative aft
  double kb = 0;               // [m] centre of buoyancy above the keel (T below the waterline)
  double block_coefficient = 0;       // C_B = ∇/(Lpp B T)
  double prismatic_coefficient = 0;   // C_P = ∇/(A_M Lpp)
  double midship_coefficient = 0;     // C_M = A_M/(B T)
  double waterplane_coefficient = 0;  // C_WP = A_WP/(Lpp B)
  double transom_area = 0;     // [m²] immersed section area at the aft end of the grid
  double bulb_area = 0;        // [m²] section area at the FP when the hull extends forward of it
  double bulb_centre_height = 0;  // [m] centroid of that section above the keel (T below the waterline)
};
HullParticulars computeParticulars(const HullGrid& grid, double length_pp);

// Arc length of the design waterline from the FP (the forward end of Y(x,0) > 0) to the fore shoulder and the
// longitudinal distance between them: the s_FS and l_FS of the paper's wave-number correction (eq 12). The
// paper does not define the shoulder: by default it is the first station, going aft, where Y(x,0) reaches its
// maximum (to 1e-6); `shoulder_distance` > 0 [m] puts it that far aft of the FP instead.
struct ForeShoulder {
  double arc_length = 0;  // [m] s_FS
  double distance = 0;    // [m] l_FS
};
ForeShoulder foreShoulder(const HullGrid& grid, double shoulder_distance = 0.0);

}  // namespace maris::ship
