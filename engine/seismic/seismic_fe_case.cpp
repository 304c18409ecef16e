// One finite-element run of the scene: mesh → model → boundary drive → explicit integration, with
// stations along the reef flat (the box: along the seabed) and, for the box, the free field at A and B.
#include <cmath>
#include <numbers>

#include "core/checked_count.hpp"

#include "seismic/fe_drive.hpp"
#include "seismic/fe_solver.hpp"
#include "seismic/seismic_live.hpp"
#include "seismic/seismic_solve.hpp"

namespace maris::seismic {

namespace {

// Highest node of column i that carries solid (the reef or seabed surface).
int topSolidNode(const FeModel& model, int i) {
  const FeMesh& m = model.mesh;
  for (int j = m.ny; j >= 0; --j)
    if (model.solid_mass[m.node(i, j)] > 0.0) return m.node(i, j);
  return m.node(i, 0);
}

}  // namespace

FeCase runFeCase(const SeismicParameters& p, double angle_deg, bool water, bool snapshots, RunContext& ctx,
                 bool coarse_companion, FeCaseHandOver* live) {
  SeismicParameters q = p;
  q.include_water = water;
  const FeModel model = buildFeModel(buildMesh(q, water, coarse_companion));
  const FeMesh& m = model.mesh;
  const FreeField field(seabedMaterial(q), waterLayer(q), waveType(q), angle_deg * std::numbers::pi / 180.0);

  FeCase out;
  out.angle_deg = angle_deg;
  out.water = water;
  out.element_size = m.delta;
  out.stable_step = model.stable_step;
  out.time_step = p.courant_fraction * model.stable_step;
  out.steps = checkedCount(p.duration / out.time_step, kMaxTimeSteps, "parameters.solver.courant_fraction",
                           "time steps over solver.duration");
  out.cell_count = static_cast<int>(model.solid_cells.size() + model.water_cells.size());
  out.nx = m.nx;
  out.ny = m.ny;
  out.x0 = m.x0;
  out.y0 = m.y0;

  // Stations: the reef flat −L/2..L/2, or the middle half of the box's seabed.
  const bool reef = p.model == "reef";
  const double half = reef ? 0.5 * p.flat_width : 0.25 * m.nx * m.delta;
  FeRunSettings settings;
  settings.time_step = out.time_step;
  settings.steps = out.steps;
  settings.snapshot_count = snapshots ? p.snapshot_count : 0;
  for (int k = 0; k < p.station_count; ++k) {
    const double x = -half + 2.0 * half * k / (p.station_count - 1);
    const int i = std::clamp(static_cast<int>(std::lround((x - m.x0) / m.delta)), 0, m.nx);
    out.station_x.push_back(m.nodeX(i));
    settings.record_nodes.push_back(reef ? topSolidNode(model, i) : m.node(i, static_cast<int>(std::lround(-m.y0 / m.delta))));
  }
  const int i_mid = m.nx / 2;
  const int seabed_node = m.node(i_mid, static_cast<int>(std::lround(-m.y0 / m.delta)));
  const int surface_node = m.node(i_mid, m.ny);
  const bool probes = !reef;
  if (probes) {
    settings.record_nodes.push_back(seabed_node);
    settings.record_nodes.push_back(surface_node);
  }

  const double arrival = arrivalAtOrigin(q, field);
  const auto incident = incidentFunction(q, arrival);
  ctx.progress(0.0, "free field on the boundary");
  BoundaryDrive drive(model, field, incident, out.time_step, out.steps, &ctx);
  // What `run` recorded so far (samples 0..n): stations, the incident displacement at the same times
  // and, for the box, FE and free field at B and A. Used for the finished run and for the copies
  // handed to the partial results, so both hold the same numbers. `drawn_only`: of the stations only
  // those in table "station_histories" (edges and centre); the others stay empty (a 13th of the copy).
  auto collect = [&](const FeRunResult& run, FeCase& c, bool drawn_only) {
    const long last = static_cast<long>(run.ux.front().size()) - 1;
    const int last_station = p.station_count - 1;
    c.ux.resize(p.station_count);
    c.uy.resize(p.station_count);
    for (int k = 0; k <= last_station; ++k) {
      if (drawn_only && k != 0 && k != last_station / 2 && k != last_station) continue;
      c.ux[k] = run.ux[k];
      c.uy[k] = run.uy[k];
    }
    for (long n = 0; n <= last; ++n) c.incident.push_back(incident(n * out.time_step));
    if (!probes) return;
    const std::size_t b = p.station_count, a = b + 1;
    c.seabed_fe_ux = run.ux[b];
    c.seabed_fe_uy = run.uy[b];
    c.probe_fe_uy = run.uy[a];
    for (long n = 0; n <= last; ++n) {
      const Eigen::Vector2d ub = drive.freeFieldDisplacement(seabed_node, n);
      c.seabed_ff_ux.push_back(ub.x());
      c.seabed_ff_uy.push_back(ub.y());
      c.probe_ff_uy.push_back(water ? drive.freeFieldDisplacement(surface_node, n).y() : ub.y());
    }
  };
  if (live) {
    // Runs in this case's worker thread; reads only. The frame is the wave field at step n.
    settings.after_step = [&](long n, const FeState& s, const FeRunResult& so_far) {
      if (!live->requested()) return;
      FeCase copy = out;  // the case's description (stations, grid); its records are still empty
      collect(so_far, copy, true);
      if (snapshots && p.snapshot_count > 0) {
        // Only at the nodes the frame draws (the snapshots' expression): the rest stays 0, unused.
        std::vector<double> magnitude(m.nodeCount(), 0.0);
        const FrameStride stride = frameStride(m.nx, m.ny);
        for (int j = 0; j <= m.ny; j += stride.j)
          for (int i = 0; i <= m.nx; i += stride.i)
            magnitude[m.node(i, j)] = nodalDisplacement(model, s, m.node(i, j)).norm();
        copy.snapshot_time.push_back(n * out.time_step);
        copy.snapshot_magnitude.push_back(std::move(magnitude));
      }
      live->deliver(std::move(copy));
    };
  }
  const FeRunResult run = runExplicit(model, &drive, FeState::zero(m.nodeCount()), settings, ctx);
  collect(run, out, false);
  for (const auto& s : run.snapshots) {
    out.snapshot_time.push_back(s.time);
    out.snapshot_magnitude.push_back(s.magnitude);
  }
  return out;
}

}  // namespace maris::seismic
