#include "seismic/fe_solver.hpp"

#include <cmath>
#include <sstream>

#include "core/errors.hpp"

namespace maris::seismic {

FeState FeState::zero(int node_count) {
  FeState s;
  for (auto* v : {&s.ux, &s.uy, &s.vx, &s.vy, &s.phi, &s.phi_dot}) v->assign(node_count, 0.0);
  return s;
}

Eigen::Vector2d nodalDisplacement(const FeModel& model, const FeState& s, int node) {
  if (model.solid_mass[node] > 0.0) return {s.ux[node], s.uy[node]};
  if (model.water_mass[node] <= 0.0) return {0.0, 0.0};
  const FeMesh& m = model.mesh;
  const int stride = m.nx + 1, i = node % stride, j = node / stride;
  auto wet = [&](int ii, int jj) {
    return ii >= 0 && jj >= 0 && ii <= m.nx && jj <= m.ny && model.water_mass[jj * stride + ii] > 0.0;
  };
  auto phi = [&](int ii, int jj) { return s.phi[jj * stride + ii]; };
  // Central differences inside, second-order one-sided differences at the water's edges.
  auto derivative = [&](int di, int dj) {
    if (wet(i - di, j - dj) && wet(i + di, j + dj)) return (phi(i + di, j + dj) - phi(i - di, j - dj)) / (2 * m.delta);
    if (wet(i - di, j - dj) && wet(i - 2 * di, j - 2 * dj))
      return (3 * phi(i, j) - 4 * phi(i - di, j - dj) + phi(i - 2 * di, j - 2 * dj)) / (2 * m.delta);
    if (wet(i + di, j + dj) && wet(i + 2 * di, j + 2 * dj))
      return (-3 * phi(i, j) + 4 * phi(i + di, j + dj) - phi(i + 2 * di, j + 2 * dj)) / (2 * m.delta);
    return 0.0;
  };
  return {derivative(1, 0), derivative(0, 1)};
}

namespace {

[[noreturn]] void throwNonFinite(const FeModel& model, const FeState& s, double t, long step, double dt) {
  const FeMesh& m = model.mesh;
  for (int a = 0; a < m.nodeCount(); ++a) {
    const double values[3] = {s.ux[a], s.uy[a], s.phi[a]};
    const char* names[3] = {"displacement u_x", "displacement u_y", "water potential phi"};
    for (int q = 0; q < 3; ++q) {
      if (std::isfinite(values[q])) continue;
      std::ostringstream what, detail;
      what << "node " << a << " " << names[q] << " at x = " << m.nodeX(a % (m.nx + 1))
           << " m, y = " << m.nodeY(a / (m.nx + 1)) << " m";
      detail << "became non-finite: the explicit scheme diverged (dt = " << dt
             << " s, stable bound " << model.stable_step << " s)";
      throw SolverError(what.str(), t, step, detail.str());
    }
  }
  throw SolverError("state", t, step, "became non-finite");
}

}  // namespace

FeRunResult runExplicit(const FeModel& model, BoundaryDrive* drive, FeState s, const FeRunSettings& settings,
                        RunContext& ctx) {
  const double dt = settings.time_step;
  if (settings.enforce_stable_step && !(dt <= model.stable_step)) {
    std::ostringstream msg;
    msg << "dt = " << dt << " s exceeds the stable step " << model.stable_step
        << " s of the central-difference scheme (element bound for Δ = " << model.mesh.delta << " m)";
    throw SolverError("time step", 0.0, 0, msg.str());
  }
  const FeMesh& m = model.mesh;
  const int nn = m.nodeCount();
  const double rho_f = m.water.density;
  std::vector<double> fx(nn), fy(nn), fphi(nn);
  FeRunResult out;
  out.time_step = dt;
  out.steps = settings.steps;
  out.ux.assign(settings.record_nodes.size(), {});
  out.uy.assign(settings.record_nodes.size(), {});
  auto record = [&]() {
    for (std::size_t r = 0; r < settings.record_nodes.size(); ++r) {
      const Eigen::Vector2d u = nodalDisplacement(model, s, settings.record_nodes[r]);
      out.ux[r].push_back(u.x());
      out.uy[r].push_back(u.y());
    }
  };
  const long snap_every =
      settings.snapshot_count > 0 ? std::max(1L, settings.steps / settings.snapshot_count) : settings.steps + 1;
  auto snapshot = [&](long n) {
    FeSnapshot f;
    f.time = n * dt;
    f.magnitude.resize(nn);
    for (int a = 0; a < nn; ++a) f.magnitude[a] = nodalDisplacement(model, s, a).norm();
    out.snapshots.push_back(std::move(f));
  };
  record();

  for (long n = 0; n < settings.steps; ++n) {
    // Every step: a step of the largest allowed mesh (6e5 cells) takes tens of ms; both calls are cheap.
    ctx.throwIfCancelled();
    ctx.progress(static_cast<double>(n) / settings.steps, "time integration");
    std::fill(fx.begin(), fx.end(), 0.0);
    std::fill(fy.begin(), fy.end(), 0.0);
    std::fill(fphi.begin(), fphi.end(), 0.0);
    if (drive) drive->addForces(n, fx, fy, fphi);
    if (settings.extra_solid_forces) settings.extra_solid_forces(n, fx, fy);

    // Water first: −K_f φ, boundary, flux from the solid; φ̈^n is kept in fphi.
    addWaterInternalForces(model, model.water_cells, s.phi, fphi);
    bool finite = true;
    for (int a = 0; a < nn; ++a) {
      const double mass = model.water_mass[a];
      if (mass <= 0.0) continue;
      if (model.water_fixed[a]) {
        fphi[a] = 0.0;
        s.phi_dot[a] = 0.0;
        continue;
      }
      const double c = model.water_damping[a];
      const double r = fphi[a] - model.water_spring[a] * s.phi[a] + model.coupling[a].dot(Eigen::Vector2d(s.ux[a], s.uy[a]));
      const double rate = ((mass - 0.5 * dt * c) * s.phi_dot[a] + dt * r) / (mass + 0.5 * dt * c);
      fphi[a] = (rate - s.phi_dot[a]) / dt;
      s.phi_dot[a] = rate;
    }
    // Solid: −K u, boundary, water pressure −ρ_f φ̈ q.
    addSolidInternalForces(model, model.solid_cells, s.ux, s.uy, fx, fy);
    for (int a = 0; a < nn; ++a) {
      const double mass = model.solid_mass[a];
      if (mass > 0.0) {
        const double rx = fx[a] - model.spring_x[a] * s.ux[a] - rho_f * fphi[a] * model.coupling[a].x();
        const double ry = fy[a] - model.spring_y[a] * s.uy[a] - rho_f * fphi[a] * model.coupling[a].y();
        const double cx = 0.5 * dt * model.dashpot_x[a], cy = 0.5 * dt * model.dashpot_y[a];
        s.vx[a] = ((mass - cx) * s.vx[a] + dt * rx) / (mass + cx);
        s.vy[a] = ((mass - cy) * s.vy[a] + dt * ry) / (mass + cy);
        s.ux[a] += dt * s.vx[a];
        s.uy[a] += dt * s.vy[a];
        finite = finite && std::isfinite(s.ux[a] + s.uy[a]);
      }
      if (model.water_mass[a] > 0.0) {
        s.phi[a] += dt * s.phi_dot[a];
        finite = finite && std::isfinite(s.phi[a]);
      }
    }
    if (!finite) throwNonFinite(model, s, (n + 1) * dt, n + 1, dt);
    record();
    if ((n + 1) % snap_every == 0) snapshot(n + 1);
    if (settings.after_step) settings.after_step(n + 1, s, out);
  }
  ctx.progress(1.0, "time integration");
  out.final_state = std::move(s);
  return out;
}

}  // namespace maris::seismic
