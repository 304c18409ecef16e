// Shared set-up for the FE tests: small models built from the scene's own parameter struct.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "seismic/fe_drive.hpp"
#include "seismic/fe_solver.hpp"
#include "seismic/seismic_inputs.hpp"
#include "seismic/seismic_parameters.hpp"

namespace maris::seismic::testing {

// The paper's verification box (§3.4) materials with a chosen size and mesh frequency.
inline SeismicParameters boxParameters(bool water, double cutoff_hz, double half_width, double seabed_depth) {
  SeismicParameters p;
  p.model = "box";
  p.include_water = water;
  p.compare_without_water = false;
  p.seabed_density = 2700.0;
  p.seabed_vs = 1800.0;
  p.seabed_vp = 4500.0;
  p.lateral_water_width = half_width;
  p.seabed_thickness = seabed_depth;
  p.cutoff_frequency = cutoff_hz;
  return p;
}

inline double maxOf(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }
inline double meanOf(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }

inline double peakAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

struct DrivenRun {
  FeModel model;
  FeRunResult result;
  std::vector<std::vector<double>> free_ux, free_uy;  // free field at the recorded nodes
};

// Runs the model under a B-spline pulse of length `pulse` [s] reaching the origin at `arrival` [s].
inline DrivenRun runDriven(const SeismicParameters& p, double angle_deg, WaveType type, double pulse, double arrival,
                           double duration, const std::vector<int>& record_nodes_ij_pairs_flat,
                           double amplitude = 1.0) {
  DrivenRun run{buildFeModel(buildMesh(p, p.include_water)), {}, {}, {}};
  const FreeField field(seabedMaterial(p), waterLayer(p), type, angle_deg * std::numbers::pi / 180.0);
  const double dt = 0.8 * run.model.stable_step;
  const long steps = static_cast<long>(std::ceil(duration / dt));
  BoundaryDrive drive(run.model, field, [&](double t) { return amplitude * bsplinePulse(t - arrival, pulse); }, dt,
                      steps);
  FeRunSettings s;
  s.time_step = dt;
  s.steps = steps;
  for (std::size_t k = 0; k + 1 < record_nodes_ij_pairs_flat.size(); k += 2)
    s.record_nodes.push_back(run.model.mesh.node(record_nodes_ij_pairs_flat[k], record_nodes_ij_pairs_flat[k + 1]));
  RunContext ctx;
  run.result = runExplicit(run.model, &drive, FeState::zero(run.model.mesh.nodeCount()), s, ctx);
  for (int node : s.record_nodes) {
    run.free_ux.emplace_back();
    run.free_uy.emplace_back();
    for (long n = 0; n <= steps; ++n) {
      const auto u = drive.freeFieldDisplacement(node, n);
      run.free_ux.back().push_back(u.x());
      run.free_uy.back().push_back(u.y());
    }
  }
  return run;
}

}  // namespace maris::seismic::testing
