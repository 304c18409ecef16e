// Seismic input of the explicit FE model by the boundary substructure method (paper eq 3,
// written out for the discrete model): at every step the boundary (b) nodes receive
//   F_b = M_bb ü⁰ + C_b u̇⁰ + K_b u⁰ + [K u⁰]_b (cells touching b only) + coupling terms,
// i.e. the residual of the full discrete equations at the b nodes under the free field u⁰ of the
// topography-free model. With lumped mass this equals the classical viscous-spring equivalent nodal
// forces with σ⁰·n replaced by its consistent discrete form (a DRM whose layer is the absorbing layer).
// The absorber then acts on u − u⁰ only, so the scattered field leaves the model.
// The free field comes from FreeFieldSynthesis: one history per grid row, delayed by p·x per node.
#pragma once

#include <functional>
#include <vector>

#include "core/run_context.hpp"
#include "seismic/fe_model.hpp"
#include "seismic/free_field_synthesis.hpp"

namespace maris::seismic {

class BoundaryDrive {
 public:
  // `incident(t)`: incident displacement at the origin [m] at time t [s]; the FE clock starts at 0 and
  // runs `steps` steps of `dt`. Histories are synthesised once here (one per grid row); with a
  // context, cancellation is checked per row (throws RunCancelled).
  BoundaryDrive(const FeModel& model, const FreeField& field, const std::function<double(double)>& incident,
                double dt, long steps, const RunContext* ctx = nullptr);

  // Adds the equivalent nodal forces at step n (time n·dt) into per-node arrays (b nodes only).
  void addForces(long step, std::vector<double>& fx, std::vector<double>& fy, std::vector<double>& fphi);

  // Free-field displacement [m] at a node at step n, for comparisons: the solid's for y ≤ 0, the water's above.
  Eigen::Vector2d freeFieldDisplacement(int node, long step) const;

 private:
  double sample(const std::vector<double>& history, int node, long step) const;

  const FeModel& model_;
  double dt_, p_;
  double trace_t0_;
  std::vector<SolidHistory> solid_rows_;  // per grid row (empty where unused)
  std::vector<WaterHistory> water_rows_;
  std::vector<double> ffx_, ffy_, ffphi_;  // free field at layer nodes (per node, scratch)
  std::vector<double> gx_, gy_, gphi_;     // −K u⁰ of the layer cells (per node, scratch)
};

}  // namespace maris::seismic
