// The shift-invert Arnoldi solver of the banded pencil (riser_modes_krylov) against the dense solvers of
// riser_modes at n ≤ 199, against the closed form of a tensioned beam at n = 1000, and its failure and
// cancellation paths.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "core/errors.hpp"
#include "riser/riser_modes_krylov.hpp"
#include "riser/riser_references.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"
#include "engine/release_only.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

struct Solved {
  RiserModel model;
  StaticSolution statics;
};

Solved solved(const RiserParameters& p) {
  Solved s{buildRiserModel(p), {}};
  RunContext context;
  s.statics = solveStatics(s.model, context);
  return s;
}

// |cos| of the angle between two mode shapes (node displacements, or twists for a torsion mode).
double shapeAlignment(const RiserModes& a, const RiserModes& b, std::size_t k) {
  double dot = 0, na = 0, nb = 0;
  for (std::size_t node = 0; node < a.shapes[k].size(); ++node) {
    dot += a.shapes[k][node].dot(b.shapes[k][node]);
    na += a.shapes[k][node].squaredNorm();
    nb += b.shapes[k][node].squaredNorm();
  }
  if (na == 0 && nb == 0) {
    for (std::size_t i = 0; i < a.twists[k].size(); ++i) {
      dot += a.twists[k][i] * b.twists[k][i];
      na += a.twists[k][i] * a.twists[k][i];
      nb += b.twists[k][i] * b.twists[k][i];
    }
  }
  return std::abs(dot) / std::sqrt(na * nb);
}

// A mode whose frequency has a (nearly) equal neighbour: its shape is any vector of the pair's plane.
bool paired(const std::vector<double>& w, std::size_t k) {
  return (k > 0 && w[k] / w[k - 1] - 1 < 1e-6) || (k + 1 < w.size() && w[k + 1] / w[k] - 1 < 1e-6);
}

// The default riser (bent by its 1 m/s current, torsion on) at n segments, no time integration.
RiserParameters defaultRiser(int n) {
  RiserParameters p;
  p.segment_count = n;
  p.end_time = 0.0;
  p.stress_times.clear();
  return p;
}

// Lowest `count` frequencies of the pencil by a dense solve: the null space Z of C (column-pivoted QR of Cᵀ), then
// the eigenvalues of (ZᵀMZ)⁻¹ ZᵀKZ, positive real ones above the free motions.
std::vector<double> denseFrequencies(const DensePencil& pencil, int count) {
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(pencil.constraints.transpose());
  qr.setThreshold(1e-10);
  const Eigen::Index n = pencil.stiffness.rows(), rank = qr.rank();
  const Eigen::MatrixXd q = qr.householderQ();
  const Eigen::MatrixXd z = q.rightCols(n - rank);
  const Eigen::MatrixXd mr = z.transpose() * pencil.mass * z, kr = z.transpose() * pencil.stiffness * z;
  Eigen::EigenSolver<Eigen::MatrixXd> eig(mr.ldlt().solve(kr), false);
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<double> w;
  for (Eigen::Index k = 0; k < eig.eigenvalues().size(); ++k) {
    const std::complex<double> l = eig.eigenvalues()[k];  // the free spin of the pinned chain: |λ| ≈ 1e-16 largest
    if (l.real() > 1e-12 * largest && std::abs(l.imag()) < 1e-6 * l.real()) w.push_back(std::sqrt(l.real()));
  }
  std::sort(w.begin(), w.end());
  w.resize(std::min<std::size_t>(w.size(), count));
  return w;
}

// Arnoldi against a dense solve of the same banded pencil: the Krylov part alone, without the differencing.
// The pencil's condition (highest over lowest ω², 2e6 at n = 50, 1.5e8 at n = 150) bounds what either can resolve.
// Measured on the ten lowest: ≤ 6e-12 at n = 50 (tolerance 1e-10); at n = 150 ≤ 9e-11 from the third mode on and
// 1.3e-10, 5.7e-10 on the first pair (split by 1e-5 only, so each member is sensitive): tolerance 2e-9 there.
// The pencil is differenced from the right-hand side, so its rounding moves these figures: after the right-hand
// side was made cheaper (same equations, other rounding) the third mode at n = 150 differed by 1.9e-10, the others
// from the third on by ≤ 1e-10: tolerance 5e-10 from the third mode on at n = 150.
// Under the sanitizers n = 50 only (the same code; the dense O(n³) solves at n = 150 cost minutes there).
TEST(RiserModesKrylov, MatchesADenseSolveOfTheSamePencil) {
  for (int n : {50, 150}) {
    if (::maris::test::kSanitizedBuild && n != 50) continue;
    const Solved s = solved(defaultRiser(n));
    RunContext context;
    const RiserModes krylov = computeModesKrylov(s.model, s.statics, 10, context);
    const std::vector<double> dense = denseFrequencies(denseModesPencil(s.model, s.statics), 10);
    ASSERT_EQ(krylov.frequencies.size(), 10u);
    ASSERT_EQ(dense.size(), 10u);
    for (std::size_t k = 0; k < 10; ++k) {
      const double tolerance = n == 50 ? 1e-10 : k >= 2 ? 5e-10 : 2e-9;
      EXPECT_NEAR(krylov.frequencies[k], dense[k], tolerance * dense[k]) << "n = " << n << " mode " << k + 1;
    }
  }
}

// Against computeModes (dense eigen solve of the differenced accelerations, joint coordinates), frequencies and
// shapes up to sign (pairs of equal frequency excepted). computeModes' own error grows about as n⁴ (the next test
// shows it is that solver's, not this one's): measured 2e-8 on ω₁ at n = 50 and 1.5e-6 at n = 150, 1e-9 or less
// from the fifth mode on at n = 50. Tolerances 1e-7 (n = 50) and 4e-6 (n = 150); shapes 1e-9.
// Under the sanitizers n = 50 only (the same code; the dense solves at n = 150 cost minutes there).
TEST(RiserModesKrylov, AgreesWithTheDenseJointSolverWithinItsRoundOff) {
  for (int n : {50, 150}) {
    if (::maris::test::kSanitizedBuild && n != 50) continue;
    const Solved s = solved(defaultRiser(n));
    RunContext context;
    const RiserModes krylov = computeModesKrylov(s.model, s.statics, 10, context);
    const RiserModes joint = computeModes(s.model, s.statics, 10);
    ASSERT_EQ(krylov.frequencies.size(), 10u);
    ASSERT_EQ(joint.frequencies.size(), 10u);
    for (std::size_t k = 0; k < 10; ++k) {
      const double w = krylov.frequencies[k];
      EXPECT_NEAR(w, joint.frequencies[k], (n == 50 ? 1e-7 : 4e-6) * joint.frequencies[k]) << "n = " << n << " mode " << k + 1;
      if (!paired(joint.frequencies, k)) {
        EXPECT_NEAR(shapeAlignment(krylov, joint, k), 1.0, 1e-9) << "n = " << n << " mode " << k + 1;
      }
    }
  }
}

// Without torsion and current a straight riser has pairs of exactly equal frequencies (two transverse planes); a
// Krylov space grown from one vector could miss one member of each. Both must be found, as the dense solver finds
// them (same tolerance as above at n = 60).
TEST(RiserModesKrylov, FindsBothMembersOfEqualFrequencyPairs) {
  RiserParameters p = defaultRiser(60);
  p.current_speed_surface = p.current_speed_seabed = 0.0;
  p.torsion = false;
  const Solved s = solved(p);
  RunContext context;
  const RiserModes krylov = computeModesKrylov(s.model, s.statics, 10, context);
  const RiserModes joint = computeModes(s.model, s.statics, 10);
  ASSERT_EQ(krylov.frequencies.size(), 10u);
  for (std::size_t k = 0; k < 10; ++k) EXPECT_NEAR(krylov.frequencies[k], joint.frequencies[k], 1e-7 * joint.frequencies[k]);
  for (std::size_t k = 0; k < 10; k += 2) EXPECT_NEAR(krylov.frequencies[k + 1], krylov.frequencies[k], 1e-9 * krylov.frequencies[k]);
}

// The segment method converges at second order to the beam with rotary inertia: ω₁(n) = ω∞ + c/n² + O(n⁻⁴), so
// successive differences at n = 40, 80, 160, 320 shrink fourfold. Measured 4.0001 and 4.0000; computeModes gives
// 4.85 at n = 40, 80, 160 (its round-off, see above). Tolerance ±0.01. The limit lies 3e-5 below eq (66) (rotary
// inertia of the 0.1 m rod, (kπ r_g)² size): tolerance 1e-4 on ω at n = 320 against eq (66).
TEST(RiserModesKrylov, ConvergesAtSecondOrderInTheSegmentCount) {
  std::vector<double> w;
  for (int n : {40, 80, 160, 320}) {
    const Solved s = solved(test::tensionedBeam(n));
    RunContext context;
    w.push_back(computeModesKrylov(s.model, s.statics, 1, context).frequencies.at(0));
  }
  EXPECT_NEAR((w[0] - w[1]) / (w[1] - w[2]), 4.0, 0.01);
  EXPECT_NEAR((w[1] - w[2]) / (w[2] - w[3]), 4.0, 0.01);
  const double k = pi / 10.0, exact = k * std::sqrt(100.0 + k * k * 1000.0);
  EXPECT_NEAR(w[3], exact, 1e-4 * exact);
}

// n = 1000: the ten lowest modes (five pairs) of the default riser, ascending, against the same run at n = 500
// (the O(1/n²) error of the segment method: ω₁ moves by 1.1e-6 between them, measured): tolerance 1e-5.
TEST(RiserModesKrylov, TenLowestModesAtThousandSegments) {
  MARIS_RELEASE_ONLY("RiserModesKrylov.MatchesADenseSolveOfTheSamePencil (ten lowest modes of the default riser, n = 50)");
  std::vector<double> previous;
  for (int n : {500, 1000}) {
    const Solved s = solved(defaultRiser(n));
    RunContext context;
    std::string method;
    const RiserModes modes = computeModesKrylov(s.model, s.statics, 10, context, &method);
    ASSERT_EQ(modes.frequencies.size(), 10u) << method;
    EXPECT_NE(method.find("Arnoldi"), std::string::npos);
    for (std::size_t k = 1; k < 10; ++k) EXPECT_GE(modes.frequencies[k], modes.frequencies[k - 1]);
    ASSERT_EQ(modes.shapes[0].size(), static_cast<std::size_t>(n + 2));
    if (!previous.empty()) {
      const double tolerance = 1e-5;
      for (std::size_t k = 0; k < 10; ++k)
        EXPECT_NEAR(modes.frequencies[k], previous[k], tolerance * previous[k]) << "mode " << k + 1;
    }
    previous = modes.frequencies;
  }
}

// A run that cannot converge (one restart, an unreachable tolerance) is a SolverError naming the stage and saying how
// far it got, not a silent shortfall of modes.
TEST(RiserModesKrylov, ReportsConvergenceFailure) {
  const Solved s = solved(defaultRiser(200));
  RunContext context;
  KrylovSettings settings;
  settings.max_restarts = 1;
  settings.tolerance = 1e-300;
  try {
    computeModesKrylov(s.model, s.statics, 10, context, nullptr, settings);
    FAIL() << "no error";
  } catch (const SolverError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("natural frequencies"), std::string::npos) << what;
    EXPECT_NE(what.find("converged"), std::string::npos) << what;
    EXPECT_NE(what.find("operator applications"), std::string::npos) << what;
  }
}

// The cancel flag is read before every operator application: a raised flag stops the solve with RunCancelled.
TEST(RiserModesKrylov, StopsWhenCancelled) {
  const Solved s = solved(defaultRiser(300));
  std::atomic<bool> cancel{true};
  RunContext context(nullptr, &cancel);
  EXPECT_THROW(computeModesKrylov(s.model, s.statics, 10, context), RunCancelled);
}

// The scene computes the modes of a long riser (n = 300) with the Krylov solver and says so in the statistics.
TEST(RiserModesKrylov, SceneUsesItAboveTheDenseLimit) {
  RunContext context;
  const Results r = solveRiser(defaultRiser(300), context);
  const Table* modes = r.findTable("modes");
  ASSERT_NE(modes, nullptr);
  EXPECT_EQ(modes->columns.front().values.size(), 6u);
  EXPECT_NE(r.stats.method.find("shift-invert Arnoldi"), std::string::npos) << r.stats.method;
}

// The work estimate: the dense solve's uninterruptible seconds and its N² memory up to n = 199; nothing of either
// above (the Krylov solver stops between iterations and stores O(n)), so n = 2000 stays within the limits.
TEST(RiserModesKrylov, WorkEstimateCountsTheDenseSolveOnly) {
  const WorkEstimate dense = estimateRiserWork(defaultRiser(199));
  EXPECT_GT(dense.seconds.value, 0.0);
  EXPECT_GT(dense.memory_bytes.value, 48.0 * 600 * 600);
  const WorkEstimate krylov = estimateRiserWork(defaultRiser(2000));
  EXPECT_EQ(krylov.seconds.value, 0.0);
  EXPECT_LT(krylov.memory_bytes.value, 1e8);
  EXPECT_TRUE(workLimitErrors(krylov).empty()) << describeErrors(workLimitErrors(krylov));
}

// Dense up to n = 199, Krylov above; internal flow above n = 199 has no solver (the state-space problem is dense).
TEST(RiserModesKrylov, MethodFollowsTheSegmentCount) {
  EXPECT_EQ(modesMethod(buildRiserModel(defaultRiser(199))), ModesMethod::Dense);
  EXPECT_EQ(modesMethod(buildRiserModel(defaultRiser(200))), ModesMethod::Krylov);
  RiserParameters flowing = defaultRiser(200);
  flowing.internal_flow_speed = 5.0;
  EXPECT_EQ(modesMethod(buildRiserModel(flowing)), ModesMethod::None);
}

}  // namespace
}  // namespace maris::riser
