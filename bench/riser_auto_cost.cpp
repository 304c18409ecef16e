// The weights of the `auto` integrator choice (riser_integrator_cost), measured: the CPU cost of one chart residual,
// one banded Newton solve and one Newton-matrix refresh of the implicit integrator, each in units of one explicit
// right-hand side (evaluateRhs) of the same model, and the right-hand side's cost per segment, on the paper's case 5
// (riser_paper_case5_j3: 500 m, torsion, current) and the peer riser (riser_peer_tensioned: 100 m, 1 m/s current),
// joint (J3) and absolute (A3) coordinates, at the static shape with every segment turning slowly (as
// bench_riser_rhs_cost), chart step h = 0.05 s (β' = h²/4, γ' = h/2).
//   bench_riser_auto_cost [repeats=3] [n list, default 20,50,100,200,400]
// Prints a markdown table: per row the minimum over the repeats of each cost and the spread (max/min) of the
// right-hand side's, and the balance evaluations per refresh the twin Newton matrix counted.
// The prediction's form (riser_integrator_cost.cpp): implicit step = ν (residual + solve), refresh = balances +
// factorisation; factorisation = refresh − balances (in right-hand sides) is printed for that constant.
// Then the wave weight: the riser's batch of wave kinematics (core/ocean_kinematics_batch, with the riser's
// truncation) at the 3(n + 1) Gauss points of the static shape of riser_vessel_rao_sea (100 m in 100 m of water,
// JONSWAP Hs 6 m, Tp 10 s, 200 components), a new time at each call as in a run, in ns per point and component.
// Times are thread CPU seconds; on a shared machine they are upper bounds.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/ocean_kinematics_batch.hpp"
#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_implicit.hpp"
#include "riser/riser_joint_newton.hpp"
#include "riser/riser_newton.hpp"
#include "riser/riser_statics.hpp"
#include "riser/riser_waves.hpp"
#include "bench_clock.hpp"
#include "riser_bench_run.hpp"
#include "riser_moving_state.hpp"

using namespace maris;
using namespace maris::riser;

namespace {

using bench::builtinRiserModel;
using bench::movingState;

struct Cost {
  double best = 1e300, worst = 0.0;  // [s] per call
};

Cost timeCalls(int repeats, long calls, const std::function<void()>& call) {
  Cost c;
  for (int r = 0; r < repeats; ++r) {
    const double t0 = bench::threadCpuSeconds();
    for (long k = 0; k < calls; ++k) call();
    const double per = (bench::threadCpuSeconds() - t0) / static_cast<double>(calls);
    c.best = std::min(c.best, per);
    c.worst = std::max(c.worst, per);
  }
  return c;
}

std::vector<int> segmentCounts(const char* text) {
  std::vector<int> out;
  std::stringstream s(text ? text : "20,50,100,200,400");
  std::string item;
  while (std::getline(s, item, ','))
    if (std::atoi(item.c_str()) > 0) out.push_back(std::atoi(item.c_str()));
  return out;
}

// ns per Gauss point and wave component of the riser's batch (minimum over the repeats) and the spread.
void timeWaves(int repeats, const std::vector<int>& counts) {
  std::printf("\n| sea | n | Gauss points | components | kinematics [us] | ns per point and component | spread |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const int n : counts) {
    const std::string path = "scenarios/riser/riser_vessel_rao_sea.json";
    RiserParameters p = riserBinder().read(scenarioFromText(std::string(*builtinResource(path)), path).parameters);
    p.segment_count = n;
    p.length = 100.0;
    p.seabed_level = -100.0;
    p.bottom_z = -100.0;
    p.wave_peak_period = 10.0;
    p.wave_component_count = 200;
    const RiserModel m = buildRiserModel(p);
    const std::vector<Eigen::Vector3d> points = bench::staticGaussPointsBelowWaterLevel(m);
    std::vector<ocean::FluidKinematics> out(points.size());
    ocean::WaveKinematicsBatch::Scratch scratch;
    const long calls = std::max(50L, 200000L / (n + 1));
    long k = 0;
    double sink = 0.0;
    const Cost c = timeCalls(repeats, calls, [&] {
      m.sea->batch->evaluate(points.data(), points.size(), 30.0 + 0.01 * static_cast<double>(k++), 1.0, 0.0, scratch,
                             out.data());
      sink += out[0].velocity.x();
    });
    const double per = 1e9 * c.best / (static_cast<double>(points.size()) * static_cast<double>(m.sea->field.size()));
    std::printf("| vessel_rao_sea | %d | %zu | %zu | %.1f | %.2f | %.2f |%s\n", n, points.size(), m.sea->field.size(),
                1e6 * c.best, per, c.worst / c.best, std::isfinite(sink) ? "" : " non-finite");
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const std::vector<int> counts = segmentCounts(argc > 2 ? argv[2] : nullptr);
  constexpr double kStep = 0.05, kRate = 1.0 / kStep;
  std::printf("| case | variant | n | rhs [us] (per segment) | spread | residual | solve | refresh | balances per "
              "refresh | factorisation = refresh - balances |\n|---|---|---|---|---|---|---|---|---|---|\n");
  for (const char* scenario : {"riser_paper_case5_j3", "riser_peer_tensioned"})
    for (const bool joint : {true, false})
      for (const int n : counts) {
        const RiserModel m = builtinRiserModel(scenario, n, joint);
        const Eigen::VectorXd y = movingState(m);
        const long calls = std::max(20L, 200000L / (n + 1));
        RiserWorkspace ws = makeWorkspace(m, kRate);
        Eigen::VectorXd dy(y.size());
        double sink = 0.0;
        const Cost rhs = timeCalls(repeats, calls, [&] {
          evaluateRhs(m, ws, 12.0, y, dy);
          sink += dy[0];
        });
        OrientationChart chart(m, kRate);
        Eigen::VectorXd q, v, r, b;
        chart.reset(y, q, v);
        Eigen::VectorXd acc = Eigen::VectorXd::Zero(chart.size());
        chart.residual(12.0, q, v, acc, r);
        acc = -r;  // the accelerations of (q, v): the residual there is zero
        const Cost residual = timeCalls(repeats, calls, [&] {
          chart.residual(12.0, q, v, acc, r);
          sink += r[0];
        });
        const IterationMatrixRequest fresh{12.0, q, v, acc, kStep / 2, kStep * kStep / 4, true};
        const IterationMatrixRequest reuse{12.0, q, v, acc, kStep / 2, kStep * kStep / 4, false};
        std::function<bool(const IterationMatrixRequest&, Eigen::VectorXd&)> solve;
        std::function<double()> balances_per_refresh;
        std::unique_ptr<JointNewtonMatrix> joint_newton;
        std::unique_ptr<ForceSpaceNewtonMatrix> force_newton;
        if (joint) {
          joint_newton = std::make_unique<JointNewtonMatrix>(m, chart, kRate);
          solve = [&](const IterationMatrixRequest& rq, Eigen::VectorXd& x) { return joint_newton->solve(rq, x); };
          balances_per_refresh = [&] {
            return static_cast<double>(joint_newton->balanceEvaluations()) / std::max(1L, joint_newton->refreshes());
          };
        } else {
          force_newton = std::make_unique<ForceSpaceNewtonMatrix>(m, chart);
          solve = [&](const IterationMatrixRequest& rq, Eigen::VectorXd& x) { return force_newton->solve(rq, x); };
          balances_per_refresh = [&] {
            return static_cast<double>(force_newton->balanceEvaluations()) / std::max(1L, force_newton->refreshes());
          };
        }
        const long refreshes = std::max(3L, calls / 40);
        const Cost refresh = timeCalls(repeats, refreshes, [&] {
          b = r;
          if (!solve(fresh, b)) std::printf("singular Newton matrix\n");
          sink += b[0];
        });
        const Cost solved = timeCalls(repeats, calls, [&] {
          b = r;
          solve(reuse, b);
          sink += b[0];
        });
        if (!std::isfinite(sink)) std::printf("non-finite result\n");
        const double unit = rhs.best, balances = balances_per_refresh();
        const double refresh_units = (refresh.best - solved.best) / unit;  // the refresh call also solves once
        std::printf("| %s | %s | %d | %.2f (%.3f) | %.2f | %.2f | %.2f | %.1f | %.0f | %.1f |\n",
                    scenario + 6, joint ? "J3" : "A3", n, 1e6 * rhs.best, 1e6 * rhs.best / (n + 1), rhs.worst / rhs.best,
                    residual.best / unit, solved.best / unit, refresh_units, balances, refresh_units - balances);
        std::fflush(stdout);
      }
  timeWaves(repeats, counts);
  return 0;
}
