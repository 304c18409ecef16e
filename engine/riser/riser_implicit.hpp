// Second-order form of the riser equations for the implicit generalized-α integrator (core/ode.hpp),
// over one chunk of time in which every orientation is given by three chart coordinates about a reference
// (see riser_integration.hpp for why and how it is used).
//
// Coordinates q (and velocities v = q̇), in the order of the first-order state:
//   top end (3): position, velocity                         (prescribed components are ignored by the pose)
//   per dynamic segment: J: θ_i (3);  A: r_i (3), θ_i (3)    R_i = R_ref,i E(θ_i), ω_body = M(θ_i) θ̇_i (ChartKind)
//   work integrals (4): q = ∫W dt (unused), v = W           (q̈ = power)
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "riser/riser_chart_maps.hpp"
#include "riser/riser_dynamics.hpp"

namespace maris::riser {

// The chart of one chunk: references, maps between (q, v) and the first-order state, and the residual.
// Its kind is the rotation vector with torsion and swing–twist without (riser_chart_maps).
class OrientationChart {
 public:
  OrientationChart(const RiserModel& m, double stabilisation_rate);

  Eigen::Index size() const { return size_; }
  // Takes the orientations of first-order state y as the references; q (θ = 0) and v from y.
  void reset(const Eigen::VectorXd& y, Eigen::VectorXd& q, Eigen::VectorXd& v);
  // (q, v) of first-order state y with the current references kept (θ = E⁻¹(R_refᵀ R), θ̇ = M⁻¹ Rᵀω);
  // the work coordinates of q are left as they are. For projecting the state after a step.
  void fromState(const Eigen::VectorXd& y, Eigen::VectorXd& q, Eigen::VectorXd& v) const;
  // Chart accelerations `acc` at (q, v), rewritten for the chart reset() makes of this state (references = the
  // current orientations, θ = 0): θ̈' = M(θ) θ̈ + Ṁ θ̇ − Ṁ(0) θ̇' (the body angular acceleration less the new
  // chart's rate term, which is zero for the rotation vector);
  // top, position and work entries unchanged. Carries the integrator's accelerations over a reset.
  void rebaseAccelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& acc) const;
  // First-order state (quaternions, angular velocities) of (q, v).
  void toState(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& y) const;
  // r = acc − a(t, q, v), a from the O(n) solve of riser_dynamics mapped to the chart.
  void residual(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& acc,
                Eigen::VectorXd& r);
  // Per dynamic segment k: the map of its chart accelerations (r̈, θ̈) to x = (a_{A_i}, α_i) is
  // x = (r̈, turn_k θ̈ + R Ṁ θ̇) with turn_k = R_i M(θ_i); also writes the arm d_i = l_i t_i (both at q).
  void accelerationMap(const Eigen::VectorXd& q, std::vector<Mat3>& turn, std::vector<Vec3>& arm) const;
  // Absolute coordinates: residuals of the unreduced equations (balanceResidual) at chart state (q, v),
  // chart accelerations acc and reactions F_j; used by the O(n) Newton matrix (riser_newton).
  void balance(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& acc,
               const std::vector<Vec3>& reaction, std::vector<Vec6>& segment_residual, std::vector<Vec3>& row_residual);
  // Workspace of the last residual()/balance() evaluation (reactions, pose).
  const RiserWorkspace& workspace() const { return ws_; }
  RiserWorkspace& workspace() { return ws_; }
  int perSegment() const { return per_segment_; }
  // Index in q of dynamic segment k's chart turn θ_k, and (A only) of its origin position r_k.
  Eigen::Index turnIndex(int k) const { return positionIndex(k) + (per_segment_ - 3); }
  Eigen::Index positionIndex(int k) const { return 3 + static_cast<Eigen::Index>(k) * per_segment_; }
  ChartKind kind() const { return kind_; }
  // Name of coordinate k for error messages.
  std::string name(Eigen::Index k) const;
  // The last residual() call whose iterate left the chart (rotation vector |θ_i| ≥ 5 rad, swing |θ_s| ≥ 2.8 rad;
  // the residual is then NaN):
  // at time t [s], which quantity, by how much. t is NaN if none did.
  struct ChartOverflow {
    double t = std::numeric_limits<double>::quiet_NaN();
    std::string quantity, detail;
  };
  const ChartOverflow& chartOverflow() const { return overflow_; }

 private:
  // toState; also keeps every segment's maps with their rate terms if `maps_with_rates` is given.
  void writeState(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& y,
                  std::vector<ChartMaps>* maps_with_rates) const;

  const RiserModel& m_;
  ChartKind kind_;               // SwingTwist without torsion
  RiserWorkspace ws_;
  std::vector<Mat3> reference_;  // R_ref,i per dynamic segment
  Eigen::VectorXd y_, dy_;
  std::vector<Vec6> x_;          // physical accelerations of balance()
  std::vector<ChartMaps> maps_;  // per dynamic segment, with rate terms, of the last residual()/balance()
  Eigen::Index size_ = 0;
  int per_segment_ = 3;          // J: θ; A: r, θ
  Eigen::Index work_ = 0;        // offset of the work coordinates in q
  ChartOverflow overflow_;       // written by residual()
};

}  // namespace maris::riser
