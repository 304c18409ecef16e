// Lumped-mass tether: N rigid links of length l = L/N between N + 1 nodes, the end nodes driven by the robots'
// attachment points. It checks the quasi-static catenary assumption of the paper (its Gazebo tether was a
// 150-link chain).
//
// Model (per interior node i, mass m = mu l, world frame z up):
//   m dv_i/dt = -w l e_z - c l v_i - (1/2) rho Cd d l |v_n| v_n + constraint forces,
// with w the wet weight per length, c a linear damping per length, v_n the velocity normal to the local tangent
// (Morison drag, optional) and the constraints |x_{i+1} - x_i| = l (inextensible links).
// Time step (symplectic Euler + constraint projection): v += dt f/m; x~ = x + dt v; then Lagrange multipliers
// mu_j solve J M^-1 J^T mu = -c(x~), a tridiagonal system per iteration (O(N)): the first correction runs along
// the old link directions (SHAKE), later ones along the current links (Newton on the constraints, which converges
// from much larger link rotations than SHAKE's fixed directions); v = (x_new - x_old)/dt. The links are exact to 1e-12 l^2 after every step, so
// the time step is limited only by the transverse waves (dt << l / sqrt(T/mu)), not by an axial stiffness.
//
// Static reference: staticChainProfile solves the discrete catenary of the same chain exactly (equal node weights
// w l): tan(phi_j) = tan(phi_0) + j w l / T_h for link j, two unknowns fixed by the end points.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "tether/tether_catenary.hpp"

namespace maris::tether {

struct CableProperties {
  int segment_count = 150;             // [-] N links (the paper's simulated tether: 150 links of 0.01 m)
  double length = 1.5;                 // [m] L
  double mass_per_length = 0.1;        // [kg/m] mu (0.150 kg / 1.5 m in the paper's simulation)
  double wet_weight_per_length = 0.9;  // [N/m] w, weight minus buoyancy
  double damping_per_length = 0.5;     // [N s/m^2] c, linear damping on node velocities
  double drag_coefficient = 0.0;       // [-] Cd for Morison normal drag (0: off, as in the paper)
  double diameter = 0.003;             // [m] d, for drag
  double water_density = 1000.0;       // [kg/m^3] rho
};

// Node positions of the static discrete chain in the tether plane relative to P2 (x towards P1, z up), N + 1 nodes.
// Also returns the horizontal tension per wet weight T_h/w [m]. Throws SolverError if the Newton solve fails.
struct StaticChain {
  std::vector<double> x, z;              // [m] node coordinates in the plane
  double horizontal_tension_per_weight;  // [m] T_h / w (continuous limit: 1/C)
  int iterations = 0;
};
StaticChain staticChainProfile(double span, double rise, double length, int segment_count);

// Height of the catenary above P2 at horizontal distance x from P2 [m] (cancellation-free form of
// (cosh(C (x - x0)) - cosh(C x0))/C). Precondition: c.has_geometry and c not VerticalHang.
double catenaryHeightAt(const Catenary& c, double x);

struct CableStepReport {
  int iterations = 0;           // projection iterations used
  double constraint_error = 0;  // [-] max |(|x_{i+1} - x_i|^2 - l^2)/l^2| after the step
  bool converged = false;
};

class LumpedMassCable {
 public:
  explicit LumpedMassCable(const CableProperties& properties);

  // Places the nodes on a catenary between follower point p2 and leader point p1 (equal arc lengths), at rest.
  void placeOnCatenary(const Eigen::Vector3d& p2, const Eigen::Vector3d& p1, const Catenary& catenary);
  // Sets every node position (N + 1) and zero velocity. Precondition: links of length l.
  void setPositions(const std::vector<Eigen::Vector3d>& positions);
  void setVelocities(const std::vector<Eigen::Vector3d>& velocities);

  // Advances dt seconds with the end nodes moved to p2_next and p1_next (prescribed by the robots).
  CableStepReport step(const Eigen::Vector3d& p2_next, const Eigen::Vector3d& p1_next, double dt);

  const std::vector<Eigen::Vector3d>& positions() const { return x_; }    // [m] world, N + 1 nodes
  const std::vector<Eigen::Vector3d>& velocities() const { return v_; }   // [m/s] world
  double linkLength() const { return link_; }
  int nodeCount() const { return static_cast<int>(x_.size()); }
  double kineticEnergy() const;  // [J]

 private:
  void applyLoads(double dt);
  CableStepReport project();

  CableProperties props_;
  double link_ = 0.0;       // [m] l
  double node_mass_ = 0.0;  // [kg] m = mu l
  std::vector<Eigen::Vector3d> x_, v_;        // node state (N + 1), written by step
  std::vector<Eigen::Vector3d> x_old_, dir_;  // workspace: positions before the step, old link vectors (N)
  std::vector<double> lower_, diag_, upper_, rhs_, mu_;  // workspace: tridiagonal system (N)
};

}  // namespace maris::tether
