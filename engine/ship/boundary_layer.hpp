// Boundary-layer displacement thickness along hull waterlines and the paper's tangency correction
// (Bašić et al., eqs 9–11). Each waterline is treated as a 2-D symmetric section at zero incidence, as the paper
// does with XFOIL; here with our own integral method:
//   edge velocity   linear thin-body (source sheet) theory, u_e/U = 1 + (1/π) PV∫ y'(σ)/(s − σ) dσ;
//   laminar         Thwaites (1949): θ² u_e⁶ = 0.45 ν ∫ u_e⁵ ds, H(λ) from Cebeci & Bradshaw (1977);
//   transition      forced at the trip position, or Michel's (1951) criterion, or laminar separation (λ < −0.09);
//   turbulent       Head's (1958) entrainment method, Ludwieg–Tillmann skin friction;
//   separation      turbulent H ≥ 2.4: beyond it δ* grows linearly with the slope it had at separation
//                   (the displacement surface leaves along the separating streamline: the mean wake direction).
// The correction rotates the hull slope by Δβ = arctan(dδ*/dx) (eq 10): Y_x,BL = tan(arctan Y_x + Δβ) (eq 11),
// and the corrected half-breadth is integrated from the bow, so the hull is open at the stern by about δ*.
#pragma once

#include <memory>
#include <vector>

#include "ship/hull_form.hpp"
#include "ship/michell_resistance.hpp"

namespace maris::ship {

// u_e/U at the nodes s_i of a section y(s) (s from the leading edge, ascending), from the linearised source
// sheet with piecewise-constant slopes; evaluated at panel midpoints and interpolated to the nodes, clipped to
// [0.5, 1.5] (linear theory is singular at slope discontinuities such as a transom edge).
std::vector<double> thinBodyEdgeVelocity(const std::vector<double>& s, const std::vector<double>& y);

struct BoundaryLayerProfile {
  std::vector<double> momentum_thickness;      // [m] θ at the nodes
  std::vector<double> shape_factor;            // [-] H = δ*/θ
  std::vector<double> displacement_thickness;  // [m] δ*
  int transition_index = -1;                   // first turbulent node (−1: laminar throughout)
  int separation_index = -1;                   // first separated node (−1: attached)
};

// Integral boundary layer along s (ascending from the leading edge) with edge velocity ratio ue_ratio(s),
// ship speed U [m/s], kinematic viscosity ν [m²/s] and forced transition at s_trip [m].
BoundaryLayerProfile solveBoundaryLayer(const std::vector<double>& s, const std::vector<double>& ue_ratio, double speed,
                                        double viscosity, double s_trip);

// Precomputes the edge velocity of every waterline of a grid (geometry only), then applies the tangency
// correction at any speed.
class TangencyCorrection {
 public:
  TangencyCorrection(HullGrid grid, double trip_fraction);
  // The grid with Y replaced by the corrected half-breadth at speed U [m/s] in water of viscosity ν.
  // `clamped` (optional) counts slopes whose rotated angle had to be limited to ±80°.
  HullGrid correctedGrid(double speed, double viscosity, int* clamped = nullptr) const;
  // δ* [m] of waterline j at every station (0 outside the wetted waterline), for output and tests.
  std::vector<double> displacementThickness(int waterline, double speed, double viscosity) const;
  const HullGrid& grid() const { return grid_; }

 private:
  struct Waterline {
    int bow = -1, stern = -1;        // station indices of the wetted range (stern ≤ bow), −1 if dry
    std::vector<double> s, y, ue;    // from the bow aft: arc length [m], half-breadth [m], u_e/U
  };
  HullGrid grid_;
  double trip_fraction_;
  std::vector<Waterline> waterlines_;
};

// Kochin function of the tangency-corrected hull: rebuilds the corrected grid for every speed.
class TangencyKochin : public KochinFunction {
 public:
  TangencyKochin(std::shared_ptr<const TangencyCorrection> correction, double viscosity)
      : correction_(std::move(correction)), viscosity_(viscosity) {}
  void prepare(double speed) override;
  void evaluate(double k0, double lambda, double& fine, double& coarse) override;
  bool hasCoarse() const override { return true; }
  double richardsonDivisor() const override { return std::exp2(correction_->grid().convergence_order) - 1.0; }
  double length() const override { return (correction_->grid().nx() - 1) * correction_->grid().dx; }
  double depth() const override { return correction_->grid().depth(); }
  int clampedSlopes() const { return clamped_; }

 private:
  std::shared_ptr<const TangencyCorrection> correction_;
  double viscosity_;
  std::unique_ptr<GridKochin> kochin_;
  int clamped_ = 0;
};

}  // namespace maris::ship
