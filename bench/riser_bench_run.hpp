// The riser benches' common run (bench_riser_long_sea, bench_riser_implicit_cost, bench_riser_peer): statics, the
// scene's integration timed in thread CPU seconds, and the history of the probe (and of the top force), with the
// probe error against a reference history and a CSV cache for references that take long to compute; and the
// points where a riser samples the sea (also for bench_riser_auto_cost).
#pragma once

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "bench_clock.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_integration.hpp"
#include "riser/riser_results.hpp"
#include "riser/riser_statics.hpp"

namespace maris::bench {

// The Gauss points of the drag and inertia loads on the static shape of m (model at rest, pose at t = 30 s, after the
// sea's ramp), relative to the still water level: the points where the riser samples the wave kinematics.
inline std::vector<Eigen::Vector3d> staticGaussPointsBelowWaterLevel(const riser::RiserModel& m) {
  using namespace riser;
  RunContext ctx;
  const StaticSolution st = solveStatics(m, ctx);
  const Eigen::VectorXd y = restState(m, st.orientation, st.top);
  RiserWorkspace ws = makeWorkspace(m, 0.0);
  poseFromState(m, 30.0, y, ws.pose);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= m.n; ++i)
    for (int q = 0; q < 3; ++q)
      points.push_back(ws.pose.position[i] + kGaussX[q] * m.segments[i].length * ws.pose.rotation[i].col(0) -
                       Eigen::Vector3d(0.0, 0.0, m.sea->water_level));
  return points;
}

struct ProbeHistory {
  std::vector<double> t;
  std::vector<riser::Vec3> probe;  // [m] displacement of the first probe
};

struct RiserRun {
  ProbeHistory history;
  std::vector<double> top_force_z;  // [N] at the history's times
  riser::RiserSolverStats stats;
  double cpu = 0.0;  // [s] thread CPU of the integration (statics and recording excluded)
};

// Statics, then the integration of p's plan (changed by adjust_plan first, if given) from rest in the static shape.
inline RiserRun runRiser(const riser::RiserParameters& p,
                         const std::function<void(riser::IntegrationPlan&)>& adjust_plan = {}) {
  using namespace riser;
  const RiserModel m = buildRiserModel(p);
  RunContext ctx;
  const StaticSolution s = solveStatics(m, ctx);
  Eigen::VectorXd y = restState(m, s.orientation, s.top);
  IntegrationPlan plan = planIntegration(m, p);
  if (adjust_plan) adjust_plan(plan);
  RiserRecorder recorder(m, p);
  recorder.sample(0.0, y, true, std::string("profile_static"));
  RiserRun out;
  const double t0 = threadCpuSeconds();
  out.stats = integrateRiser(m, p, plan, y, recorder, ctx);
  out.cpu = threadCpuSeconds() - t0;
  const Results r = recorder.finish(out.stats, s);
  const Table* h = r.findTable("history");
  out.history.t = h->find("time")->values;
  out.top_force_z = h->find("top_force_z")->values;
  const Column* d[3] = {h->find("probe_dx"), h->find("probe_dy"), h->find("probe_dz")};
  for (std::size_t k = 0; k < out.history.t.size(); ++k)
    out.history.probe.emplace_back(d[0]->values[k], d[1]->values[k], d[2]->values[k]);
  return out;
}

// A history cached as CSV rows t,x,y,z; empty unless the file holds one that reaches end_time.
inline ProbeHistory readHistory(const std::string& path, double end_time) {
  ProbeHistory h;
  std::ifstream in(path);
  double t, x, y, z;
  char c;
  while (in >> t >> c >> x >> c >> y >> c >> z) h.t.push_back(t), h.probe.emplace_back(x, y, z);
  if (h.t.empty() || std::abs(h.t.back() - end_time) > 1e-9) return {};
  return h;
}

inline void writeHistory(const std::string& path, const ProbeHistory& h) {
  std::ofstream out(path);
  out.precision(17);
  for (std::size_t k = 0; k < h.t.size(); ++k)
    out << h.t[k] << ',' << h.probe[k].x() << ',' << h.probe[k].y() << ',' << h.probe[k].z() << '\n';
}

// What the probe error is relative to: the reference's largest excursion from its start, or the range of its
// motion (the largest distance between two of its samples; O(N²) on ≈ 2000 samples, cheap enough).
enum class ErrorScale { Excursion, Range };

// Largest |r − r_ref| at the reference's samples (the run's history linearly interpolated) over the scale.
inline double probeError(const ProbeHistory& a, const ProbeHistory& ref, ErrorScale scale_kind) {
  double err = 0.0, scale = 0.0;
  std::size_t j = 0;
  for (std::size_t k = 0; k < ref.t.size(); ++k) {
    while (j + 2 < a.t.size() && a.t[j + 1] < ref.t[k]) ++j;
    const double w = std::clamp((ref.t[k] - a.t[j]) / (a.t[j + 1] - a.t[j]), 0.0, 1.0);
    const riser::Vec3 v = (1 - w) * a.probe[j] + w * a.probe[j + 1];
    err = std::max(err, (v - ref.probe[k]).norm());
    if (scale_kind == ErrorScale::Excursion) scale = std::max(scale, (ref.probe[k] - ref.probe[0]).norm());
  }
  if (scale_kind == ErrorScale::Range)
    for (std::size_t p = 0; p < ref.probe.size(); ++p)
      for (std::size_t q = p + 1; q < ref.probe.size(); ++q)
        scale = std::max(scale, (ref.probe[p] - ref.probe[q]).norm());
  return err / std::max(scale, 1e-300);
}

}  // namespace maris::bench
