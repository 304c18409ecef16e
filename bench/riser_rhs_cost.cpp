// CPU cost of one explicit right-hand side (evaluateRhs) of the peer riser (scenario riser_peer_tensioned: 100 m
// steel riser in a 1 m/s current), joint (J3) and absolute (A3) coordinates, n = 50/100/200, at a moving state:
// the static shape with every segment turning at a few hundredths of a rad/s (and, in A, its origin moving), so
// that drag, spring dampers and the velocity terms all do work. The minimum over the repeats is the cost; the
// spread (max/min) says how quiet the machine was.
//   bench_riser_rhs_cost [repeats=5] [evaluations=20000] [values.txt]
// With a file name the right-hand sides are also written there (%.17g), or, when the file exists, compared with
// it: the largest difference relative to the largest entry of its kind is printed, so that a faster right-hand
// side can be checked to give the same numbers up to rounding.
// Times are thread CPU seconds; on a shared machine they are upper bounds. The last column is the Newton iterations
// of the static shape the state starts from (riser_statics; its rounding goes through the same loads).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_statics.hpp"
#include "bench_clock.hpp"
#include "riser_moving_state.hpp"

using namespace maris;
using namespace maris::riser;

namespace {

RiserModel peerModel(int n, bool joint) { return bench::builtinRiserModel("riser_peer_tensioned", n, joint); }

using bench::movingState;

// Largest difference between two right-hand sides relative to the largest entry of the same kind (the same
// component of every segment, e.g. all angular accelerations z; the header and work entries each on their own).
double largestRelativeDifference(const RiserModel& m, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::Index first = segmentStateOffset(m, m.first_dynamic), work = workIntegralOffset(m);
  const Eigen::Index stride = segmentStateOffset(m, m.first_dynamic + 1) - first;
  auto kind = [&](Eigen::Index k) { return k < first || k >= work ? k : first + (k - first) % stride; };
  std::vector<double> scale(a.size(), 0.0), diff(a.size(), 0.0);
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    scale[kind(k)] = std::max(scale[kind(k)], std::abs(a[k]));
    diff[kind(k)] = std::max(diff[kind(k)], std::abs(a[k] - b[k]));
  }
  double largest = 0.0;
  for (std::size_t k = 0; k < scale.size(); ++k)
    if (diff[k] > 0) largest = std::max(largest, diff[k] / std::max(scale[k], 1e-300));
  return largest;
}

struct Cost {
  double best = 1e300, worst = 0.0;  // [s] per evaluation
};

Cost measure(const RiserModel& m, const Eigen::VectorXd& y, int repeats, long evaluations, Eigen::VectorXd& dy) {
  RiserWorkspace ws = makeWorkspace(m, 5.0);
  dy.resize(y.size());
  Cost c;
  double sink = 0.0;
  for (int r = 0; r < repeats; ++r) {
    const double t0 = bench::threadCpuSeconds();
    for (long k = 0; k < evaluations; ++k) {
      evaluateRhs(m, ws, 12.0, y, dy);
      sink += dy[k % dy.size()];
    }
    const double per = (bench::threadCpuSeconds() - t0) / static_cast<double>(evaluations);
    c.best = std::min(c.best, per);
    c.worst = std::max(c.worst, per);
  }
  if (!std::isfinite(sink)) std::printf("non-finite right-hand side\n");
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const long evaluations = argc > 2 ? std::max(1L, std::atol(argv[2])) : 20000;
  const std::string values_path = argc > 3 ? argv[3] : "";
  std::ifstream previous(values_path);
  const bool compare = !values_path.empty() && previous.good();
  std::ofstream values;
  if (!values_path.empty() && !compare) values.open(values_path);
  std::printf("| variant | n | us per evaluation (min of %d) | per segment [us] | spread max/min |%s statics iterations |\n",
              repeats, compare ? " largest relative difference |" : "");
  std::printf("|---|---|---|---|---|%s---|\n", compare ? "---|" : "");
  for (const bool joint : {true, false})
    for (const int n : {50, 100, 200}) {
      const RiserModel m = peerModel(n, joint);
      int statics_iterations = 0;
      const Eigen::VectorXd y = movingState(m, &statics_iterations);
      Eigen::VectorXd dy;
      const long count = evaluations * 100 / n;
      const Cost c = measure(m, y, repeats, count, dy);
      std::string diff;
      if (compare) {
        Eigen::VectorXd before(dy.size());
        for (Eigen::Index k = 0; k < dy.size(); ++k) previous >> before[k];
        char text[64];
        std::snprintf(text, sizeof text, " %.1e |", largestRelativeDifference(m, before, dy));
        diff = text;
      } else if (values.is_open()) {
        for (Eigen::Index k = 0; k < dy.size(); ++k) {
          char text[32];
          std::snprintf(text, sizeof text, "%.17g\n", dy[k]);
          values << text;
        }
      }
      std::printf("| %s | %d | %.2f | %.3f | %.2f |%s %d |\n", joint ? "J3" : "A3", n, 1e6 * c.best, 1e6 * c.best / (n + 1),
                  c.worst / c.best, diff.c_str(), statics_iterations);
      std::fflush(stdout);
    }
  return 0;
}
