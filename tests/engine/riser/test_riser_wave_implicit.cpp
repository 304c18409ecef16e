// The implicit integrator in a sea (waves, vessel RAOs, current profile, torsion) against RK4 at its small
// stability-bound step, an independent integration of the same equations: generalized-α converges to it.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/run_context.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

// The built-in floater case made short and small: 100 m riser in 100 m of water, n = 10, torsion on, 20
// components, ramp 2 s, 8 s simulated, one probe at L/2.
RiserParameters shortSea() {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_vessel_rao_sea.json");
  p.length = 100.0;
  p.segment_count = 10;
  p.torsion = true;
  p.seabed_level = -100.0;
  p.bottom_z = -100.0;
  p.wave_peak_period = 10.0;
  p.wave_component_count = 20;
  p.wave_ramp_time = 2.0;
  p.current_profile = {{0.0, 0.8, 0.0}, {50.0, 0.3, 30.0}, {100.0, 0.1, 45.0}};
  p.probes = {{50.0}};
  p.stress_times.clear();
  p.frame_count = 4;
  p.end_time = 8.0;
  return p;
}

std::vector<Eigen::Vector3d> probeHistory(const RiserParameters& p) {
  RunContext context;
  const Results r = solveRiser(p, context);
  const Table& h = *r.findTable("history");
  const auto &x = h.find("probe_dx")->values, &y = h.find("probe_dy")->values, &z = h.find("probe_dz")->values;
  std::vector<Eigen::Vector3d> out;
  for (std::size_t k = 0; k < x.size(); ++k) out.emplace_back(x[k], y[k], z[k]);
  return out;
}

// Largest distance from the reference at the common history samples, over the reference's largest excursion.
double relativeError(const std::vector<Eigen::Vector3d>& run, const std::vector<Eigen::Vector3d>& ref) {
  EXPECT_EQ(run.size(), ref.size());
  double err = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < std::min(run.size(), ref.size()); ++k) {
    err = std::max(err, (run[k] - ref[k]).norm());
    scale = std::max(scale, (ref[k] - ref[0]).norm());
  }
  EXPECT_GT(scale, 0.05);  // the probe moves (m)
  return err / scale;
}

TEST(RiserWaveImplicit, GeneralizedAlphaInASeaConvergesToRk4) {
  RiserParameters p = shortSea();
  p.integrator = "rk4";
  p.time_step = 0.0;  // half RK4's stability limit (torsion at n = 10: about 1 ms)
  const std::vector<Eigen::Vector3d> ref = probeHistory(p);
  p.integrator = "implicit";
  p.time_step = 0.025;
  const double coarse = relativeError(probeHistory(p), ref);
  p.time_step = 0.0125;
  const double fine = relativeError(probeHistory(p), ref);
  // Measured 5.9e-2, 2.8e-2, 1.35e-2, 6.5e-3 at h = 0.1, 0.05, 0.025, 0.0125 s: the implicit runs converge to RK4,
  // but at first order here (second order against their own fine-step limit in bench_riser_long_sea), an O(h)
  // term not yet traced (docs/riser.md, "Speed in a long irregular sea"). Asserted: the error halves with the
  // step (≤ 0.6×) and is within 1e-2 of the motion at 12.5 ms.
  EXPECT_LT(fine, 0.6 * coarse) << coarse << " " << fine;
  EXPECT_LT(fine, 1e-2);
}

}  // namespace
}  // namespace maris::riser
