#include "seismic/fe_drive.hpp"

#include <cmath>

#include "core/checked_count.hpp"

namespace maris::seismic {

BoundaryDrive::BoundaryDrive(const FeModel& model, const FreeField& field,
                             const std::function<double(double)>& incident, double dt, long steps,
                             const RunContext* ctx)
    : model_(model), dt_(dt), p_(field.horizontalSlowness()) {
  const FeMesh& m = model.mesh;
  // Row histories must cover t − p·x for every node: from −|p|·W/2 to T + |p|·W/2.
  const double half_width = 0.5 * m.nx * m.delta;
  const double lead = std::abs(p_) * half_width + 4.0 * dt;
  trace_t0_ = -lead;
  const int n = static_cast<int>(checkedCount((steps * dt + 2.0 * lead) / dt, kMaxStoredSamples,
                                              "parameters.solver.courant_fraction", "samples of the incident trace")) + 4;
  std::vector<double> u0(n);
  for (int k = 0; k < n; ++k) u0[k] = incident(trace_t0_ + k * dt);
  const FreeFieldSynthesis synthesis(field, u0, trace_t0_, dt, ctx);

  // Which rows have layer nodes in the solid / in the water.
  std::vector<char> row_solid(m.ny + 1, 0), row_water(m.ny + 1, 0);
  for (int a : model.layer_nodes) {
    const int j = a / (m.nx + 1);
    if (model.solid_mass[a] > 0.0) row_solid[j] = 1;
    if (model.water_mass[a] > 0.0) row_water[j] = 1;
  }
  solid_rows_.resize(m.ny + 1);
  water_rows_.resize(m.ny + 1);
  for (int j = 0; j <= m.ny; ++j) {
    if (ctx) ctx->throwIfCancelled();
    const double y = m.nodeY(j);
    if (row_solid[j]) {
      solid_rows_[j] = synthesis.solid(std::min(y, 0.0));
      auto& h = solid_rows_[j];
      h.sxx = {};
      h.syy = {};
      h.sxy = {};
    }
    if (row_water[j] && field.hasWater()) water_rows_[j] = synthesis.water(std::clamp(y, 0.0, field.water().depth));
  }
  const int nn = m.nodeCount();
  ffx_.assign(nn, 0.0);
  ffy_.assign(nn, 0.0);
  ffphi_.assign(nn, 0.0);
  gx_.assign(nn, 0.0);
  gy_.assign(nn, 0.0);
  gphi_.assign(nn, 0.0);
}

double BoundaryDrive::sample(const std::vector<double>& history, int node, long step) const {
  const int i = node % (model_.mesh.nx + 1);
  return sampleDelayed(history, trace_t0_, dt_, step * dt_ - p_ * model_.mesh.nodeX(i));
}

Eigen::Vector2d BoundaryDrive::freeFieldDisplacement(int node, long step) const {
  const int j = node / (model_.mesh.nx + 1);
  if (model_.mesh.nodeY(j) <= 0.0 && !solid_rows_[j].ux.empty())
    return {sample(solid_rows_[j].ux, node, step), sample(solid_rows_[j].uy, node, step)};
  if (!water_rows_[j].ux.empty()) return {sample(water_rows_[j].ux, node, step), sample(water_rows_[j].uy, node, step)};
  return {0.0, 0.0};
}

void BoundaryDrive::addForces(long step, std::vector<double>& fx, std::vector<double>& fy, std::vector<double>& fphi) {
  const FeModel& f = model_;
  const int stride = f.mesh.nx + 1;
  // Free field on the layer nodes, and the layer cells' internal forces under it.
  for (int a : f.layer_nodes) {
    const int j = a / stride;
    gx_[a] = gy_[a] = gphi_[a] = 0.0;
    if (f.solid_mass[a] > 0.0) {
      ffx_[a] = sample(solid_rows_[j].ux, a, step);
      ffy_[a] = sample(solid_rows_[j].uy, a, step);
    }
    if (f.water_mass[a] > 0.0 && !water_rows_[j].phi.empty()) ffphi_[a] = sample(water_rows_[j].phi, a, step);
  }
  addSolidInternalForces(f, f.layer_solid_cells, ffx_, ffy_, gx_, gy_);
  addWaterInternalForces(f, f.layer_water_cells, ffphi_, gphi_);

  // Residual of the discrete equations at the b nodes.
  for (int a : f.boundary_nodes) {
    const int j = a / stride;
    const bool wet = f.water_mass[a] > 0.0 && !water_rows_[j].phi.empty();
    const double phi_ddot = wet ? sample(water_rows_[j].phi_ddot, a, step) : 0.0;
    if (f.solid_mass[a] > 0.0) {
      const auto& h = solid_rows_[j];
      fx[a] += f.solid_mass[a] * sample(h.ax, a, step) + f.dashpot_x[a] * sample(h.vx, a, step) +
               f.spring_x[a] * ffx_[a] - gx_[a] + f.mesh.water.density * phi_ddot * f.coupling[a].x();
      fy[a] += f.solid_mass[a] * sample(h.ay, a, step) + f.dashpot_y[a] * sample(h.vy, a, step) +
               f.spring_y[a] * ffy_[a] - gy_[a] + f.mesh.water.density * phi_ddot * f.coupling[a].y();
    }
    if (wet && !f.water_fixed[a]) {
      const auto& w = water_rows_[j];
      fphi[a] += f.water_mass[a] * phi_ddot + f.water_damping[a] * sample(w.phi_dot, a, step) +
                 f.water_spring[a] * ffphi_[a] - gphi_[a] - f.coupling[a].dot(Eigen::Vector2d(ffx_[a], ffy_[a]));
    }
  }
}

}  // namespace maris::seismic
