// Natural frequencies of the linearised chain against closed forms (hanging chain, tensioned beam eq (66), cantilever, torsion),
// an independent finite-difference solution, and each other (joint vs absolute linearisation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "riser/riser_modes.hpp"
#include "riser/riser_references.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"

namespace maris::riser {
namespace {

using std::numbers::pi;

// Distinct frequencies: in 3D every planar bending mode appears twice (two transverse planes).
std::vector<double> distinctFrequencies(const RiserParameters& p, int count,
                                        Formulation linearisation = Formulation::Joint) {
  const RiserModel m = buildRiserModel(p);
  RunContext context;
  const StaticSolution s = solveStatics(m, context);
  const RiserModes modes = computeModes(m, s, 4 * count, linearisation);
  std::vector<double> out;
  for (double w : modes.frequencies)
    if (out.empty() || w > out.back() * (1 + 1e-6)) out.push_back(w);
  out.resize(std::min<std::size_t>(out.size(), count));
  return out;
}

// The three lowest distinct frequencies of riser(n) against `exact` at two segment counts n, the second twice
// the first: each relative error within its bound, and the error falling about 4× (3 to 5) from the first count
// to the second, as the segment method's O(1/n²) error does.
template <typename Riser>
void expectSecondOrderApproach(const Riser& riser, const std::vector<double>& exact,
                               const std::vector<std::pair<int, double>>& counts_and_bounds) {
  double previous[3] = {0, 0, 0};
  for (const auto& [n, bound] : counts_and_bounds) {
    const std::vector<double> w = distinctFrequencies(riser(n), 3);
    ASSERT_EQ(w.size(), 3u);
    for (int k = 0; k < 3; ++k) {
      const double error = (w[k] - exact[k]) / exact[k];
      EXPECT_LT(std::abs(error), bound) << "mode " << k + 1 << " n = " << n;
      if (previous[k] != 0) {
        EXPECT_NEAR(previous[k] / error, 4.0, 1.0) << "mode " << k + 1;
      }
      previous[k] = error;
    }
  }
}

// Pinned-pinned tensioned beam, eq (66): ω_k = (kπ/L)√(T/m* + (kπ/L)² EI/m*). L = 10 m, m* = 1 kg/m,
// EI = 1000 N·m², T = 100 N: 4.42838, 13.97616, 29.62837 rad/s. The SM errors are O(1/n²):
// +0.21 %, +0.33 %, +0.32 % at n = 10 (an independent planar prototype of the segment method (outside this repository)); tolerance 0.5 % at n = 10, and halving Δ
// must reduce each error about 4x (3 to 5).
TEST(RiserModes, TensionedPinnedBeamMatchesEquation66) {
  const std::vector<double> exact = {4.42838, 13.97616, 29.62837};
  expectSecondOrderApproach(test::tensionedBeam, exact, {{10, 5e-3}, {20, 1.5e-3}});
}

// Hanging chain (top pinned, bottom free, EI ≈ 0): ω_k = (j_0,k / 2)√(g/L), j_0,k = 2.404826,
// 5.520078, 8.653728. SM errors at n = 20: +0.007 %, +0.25 %, +1.03 % (the same prototype): tolerance 1.5 %.
TEST(RiserModes, HangingChainMatchesBesselZeros) {
  const RiserParameters p = test::chainInAir(20);
  const std::vector<double> w = distinctFrequencies(p, 3);
  const double zeros[3] = {2.404826, 5.520078, 8.653728};
  ASSERT_EQ(w.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const double exact = zeros[k] / 2 * std::sqrt(p.gravity / p.length);
    EXPECT_NEAR(w[k], exact, (k == 0 ? 5e-4 : 1.5e-2) * exact) << "mode " << k + 1;
  }
}

// Cantilever: ω_k = (β_k L)² √(EI/(μ L⁴)), β_k L = 1.875104, 4.694091, 7.854757. SM errors at n = 20:
// +0.057 %, +0.20 %, +0.33 % (the same prototype): tolerance 0.5 % (rotary inertia adds < 0.01 %).
TEST(RiserModes, CantileverMatchesEulerBernoulli) {
  RiserParameters p = test::tipLoadedCantilever(20, 0.0);
  p.point_loads.clear();
  p.added_mass_coefficient = 0.0;
  p.internal_fluid_density = 0.0;
  const std::vector<double> w = distinctFrequencies(p, 3);
  const double beta[3] = {1.875104, 4.694091, 7.854757};
  const double area = pi / 4 * (0.01 - 0.0064);
  const double mu = p.density * area, ei = test::bendingStiffness(p);
  ASSERT_EQ(w.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const double exact = beta[k] * beta[k] * std::sqrt(ei / (mu * std::pow(10.0, 4)));
    EXPECT_NEAR(w[k], exact, 5e-3 * exact) << "mode " << k + 1;
  }
}

// Pinned-pinned string (EI → 0, no gravity) on a tensioner: ω_k = (kπ/L)√(T/μ). The SM chain is a
// discrete string; its relative error has the size (kπ/n)²/24 of a second-order lumped string's
// dispersion (positive here: the rigid segments carry consistent rotary inertia; measured +3.7 % for
// k = 3, n = 10): tolerance 1.2x that, and halving Δ must cut each error by about 4 (3 to 5).
TEST(RiserModes, StringLimitMatchesTautStringFrequencies) {
  double previous[3] = {0, 0, 0};
  for (int n : {10, 20}) {
    RiserParameters p = test::calmInAir();
    p.length = 10.0;
    p.segment_count = n;
    p.outer_diameter = 0.1;
    p.inner_diameter = 0.0;
    p.added_mass_coefficient = 0.0;
    p.density = 1.0 / (pi / 4 * 0.01);  // μ = 1 kg/m
    p.youngs_modulus = 1e-6;              // EI ≈ 5e-12 N·m²: a string
    p.torsion = false;
    p.gravity = 0.0;
    p.top_condition = "tensioner";
    p.top_tension = 100.0;
    p.bottom_condition = "pinned";
    p.bottom_z = -10.0;
    const std::vector<double> w = distinctFrequencies(p, 3);
    ASSERT_EQ(w.size(), 3u);
    for (int k = 0; k < 3; ++k) {
      const double exact = (k + 1) * pi / p.length * std::sqrt(p.top_tension / 1.0);
      const double error = (w[k] - exact) / exact;
      EXPECT_LT(std::abs(error), 1.2 * std::pow((k + 1) * pi / n, 2) / 24) << "mode " << k + 1 << " n = " << n;
      if (previous[k] != 0) {
        EXPECT_NEAR(previous[k] / error, 4.0, 1.0) << "mode " << k + 1;
      }
      previous[k] = error;
    }
  }
}

// Fixed-free torsion (top clamped, bottom free, no gravity): ω_k = (2k-1)π/(2L)·√(GJ/ι).
// The torsion modes are those with torsion_share > 0.99 (the others are bending modes). The chain is a
// lumped second-order string in twist: relative error -((2k-1)π/(2n))²/24 to leading order; tolerance
// 1.2x that and a ratio of about 4 (3 to 5) when Δ is halved.
TEST(RiserModes, FixedFreeTorsionMatchesClosedForm) {
  double previous[2] = {0, 0};
  for (int n : {10, 20}) {
    RiserParameters p = test::calmInAir();
    p.length = 10.0;
    p.segment_count = n;
    p.outer_diameter = 0.1;
    p.inner_diameter = 0.08;
    p.gravity = 0.0;
    p.top_condition = "clamped";
    p.bottom_condition = "free";
    const RiserModel m = buildRiserModel(p);
    RunContext context;
    const StaticSolution s = solveStatics(m, context);
    const RiserModes modes = computeModes(m, s, 6 * n);
    std::vector<double> torsion;
    for (std::size_t k = 0; k < modes.frequencies.size(); ++k)
      if (modes.torsion_share[k] > 0.99) torsion.push_back(modes.frequencies[k]);
    ASSERT_GE(torsion.size(), 2u) << "n = " << n;
    const double wave_speed = std::sqrt(p.shear_modulus / p.density);  // √(GJ/ι) for a tube: J = polar moment
    for (int k = 0; k < 2; ++k) {
      const double exact = (2 * k + 1) * pi / (2 * p.length) * wave_speed;
      const double error = (torsion[k] - exact) / exact;
      EXPECT_LT(std::abs(error), 1.2 * std::pow((2 * k + 1) * pi / (2 * n), 2) / 24)
          << "torsion mode " << k + 1 << " n = " << n;
      if (previous[k] != 0) {
        EXPECT_NEAR(previous[k] / error, 4.0, 1.0) << "torsion mode " << k + 1;
      }
      previous[k] = error;
    }
  }
}

// Independent reference for a heavy riser: μ ÿ = (T(s) y')' - EI y'''' with T(s) = T_top - w s
// (submerged weight w, s from the top), pinned ends (y = y'' = 0), by second-order finite
// differences on N intervals (ghost points y_{-1} = -y_1), Richardson-extrapolated from N = 200 and
// 400 (remaining error O(N⁻⁴) ≈ 1e-8 relative). Returns the lowest `count` ω [rad/s].
std::vector<double> heavyRiserFiniteDifference(double length, double mu, double ei, double top_tension,
                                               double weight, int count) {
  auto solve = [&](int intervals) {
    const int size = intervals - 1;
    const double h = length / intervals;
    const double stencil[5] = {1, -4, 6, -4, 1};
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(size, size);
    for (int j = 0; j < size; ++j) {
      const double s = (j + 1) * h;
      const double t_above = top_tension - weight * (s - h / 2), t_below = top_tension - weight * (s + h / 2);
      k(j, j) += (t_above + t_below) / (h * h);
      if (j > 0) k(j, j - 1) -= t_above / (h * h);
      if (j + 1 < size) k(j, j + 1) -= t_below / (h * h);
      for (int o = -2; o <= 2; ++o) {
        int col = j + o;
        double sign = 1;
        if (col == -1 || col == size) continue;  // the support itself: y = 0
        if (col < -1) col = -col - 2, sign = -1;  // ghost y_{-1} = -y_1 (moment-free end)
        if (col > size) col = 2 * size - col, sign = -1;
        k(j, col) += sign * ei * stencil[o + 2] / std::pow(h, 4);
      }
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k / mu);
    std::vector<double> w;
    for (int c = 0; c < count; ++c) w.push_back(std::sqrt(eig.eigenvalues()[c]));
    return w;
  };
  const std::vector<double> coarse = solve(200), fine = solve(400);
  std::vector<double> out;
  for (int c = 0; c < count; ++c) out.push_back((4 * fine[c] - coarse[c]) / 3);
  return out;
}

// Heavy riser in water: 100 m steel pipe (D 0.3/0.26 m, water-filled), top tensioner 2x its submerged
// weight, bottom pinned, fully submerged, so tension falls linearly from 2wL to wL along it and EI
// matters as much as tension. SM against the finite-difference Sturm-Liouville solution: O(1/n²),
// tolerance 0.5 % at n = 20 and a ratio 3 to 5 when Δ is halved (n = 40).
TEST(RiserModes, HeavyRiserMatchesFiniteDifferenceSturmLiouville) {
  RiserParameters p = test::calmInAir();
  p.length = 100.0;
  p.outer_diameter = 0.3;
  p.inner_diameter = 0.26;
  p.torsion = false;
  p.water_level = 1.0;  // whole riser submerged
  p.seabed_level = -100.0;
  p.top_condition = "tensioner";
  p.bottom_condition = "pinned";
  p.bottom_z = -100.0;
  const double a_out = pi / 4 * 0.09, a_inn = pi / 4 * 0.26 * 0.26;
  const double wall = p.density * (a_out - a_inn), contents = p.internal_fluid_density * a_inn;
  const double mu = wall + contents + p.water_density * p.added_mass_coefficient * a_out;
  const double weight = (wall + contents - p.water_density * a_out) * p.gravity;
  p.top_tension = 2 * weight * p.length;
  const double ei = test::bendingStiffness(p);
  const std::vector<double> exact = heavyRiserFiniteDifference(p.length, mu, ei, p.top_tension, weight, 3);
  const auto riser = [p](int n) {
    RiserParameters q = p;
    q.segment_count = n;
    return q;
  };
  expectSecondOrderApproach(riser, exact, {{20, 5e-3}, {40, 1.5e-3}});
}

// The Galerkin reference of the frequency sweeps (riser_references.hpp) with tension falling with depth
// and no flow must agree with the independent finite-difference solution above (the heavy riser of the
// previous test, i_T = 2 and i_T = 1, where the tension reaches zero at the bottom). Sine modes are
// not eigenfunctions when T varies; measured differences with 24 modes ≤ 2.3e-8 (the FD solution's own
// error is ≈ 1e-8): tolerance 1e-6.
TEST(RiserModes, DepthVaryingGalerkinMatchesFiniteDifferenceSturmLiouville) {
  const double ei = 2.07e11 * pi / 64 * (std::pow(0.3, 4) - std::pow(0.26, 4));
  const double a_out = pi / 4 * 0.09, a_inn = pi / 4 * 0.26 * 0.26;
  const double wall = 7850.0 * (a_out - a_inn), contents = 1025.0 * a_inn;
  const double mu = wall + contents + 1025.0 * a_out;
  const double weight = (wall + contents - 1025.0 * a_out) * 9.81;
  for (double ratio : {2.0, 1.0}) {
    ConveyingPipe pipe;
    pipe.length = 100.0;
    pipe.mass_per_length = mu;
    pipe.fluid_mass_per_length = contents;
    pipe.ei = ei;
    pipe.top_tension = ratio * weight * 100.0;
    pipe.weight_per_length = weight;
    const std::vector<double> galerkin = conveyingPipeFrequencies(pipe, 24, 3);
    const std::vector<double> exact = heavyRiserFiniteDifference(100.0, mu, ei, pipe.top_tension, weight, 3);
    ASSERT_EQ(galerkin.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(galerkin[k], exact[k], 1e-6 * exact[k]) << "i_T = " << ratio << " mode " << k + 1;
  }
}

// Both linearisations of the same bent equilibrium (default riser in its 1 m/s current, torsion on,
// bottom on a spring so that loads depend on positions and the A position columns do not vanish):
// the absolute one has 6 coordinates per segment and 3(n+2) extra zero modes, yet its non-zero
// frequencies must equal the joint ones (see riser_modes.hpp for why). Central differences with step
// 1e-6 leave ~1e-9 relative noise (measured 2e-10): tolerance 1e-7.
TEST(RiserModes, AbsoluteAndJointLinearisationsGiveTheSameFrequencies) {
  RiserParameters p;
  p.segment_count = 10;
  p.bottom_condition = "spring";
  p.bottom_spring_stiffness = 2e5;
  p.end_time = 0.0;
  p.stress_times.clear();
  const RiserModel m = buildRiserModel(p);
  RunContext context;
  const StaticSolution s = solveStatics(m, context);
  const RiserModes joint = computeModes(m, s, 12, Formulation::Joint);
  const RiserModes absolute = computeModes(m, s, 12, Formulation::Absolute);
  ASSERT_EQ(joint.frequencies.size(), 12u);
  ASSERT_EQ(absolute.frequencies.size(), 12u);
  for (int k = 0; k < 12; ++k) {
    EXPECT_NEAR(absolute.frequencies[k], joint.frequencies[k], 1e-7 * joint.frequencies[k]) << "mode " << k + 1;
    // Same shape up to sign, except within pairs of (nearly) equal frequency, which may mix.
    double dot = 0, nj = 0, na = 0;
    for (int node = 0; node <= m.n + 1; ++node) {
      dot += joint.shapes[k][node].dot(absolute.shapes[k][node]);
      nj += joint.shapes[k][node].squaredNorm();
      na += absolute.shapes[k][node].squaredNorm();
    }
    const bool paired = (k > 0 && std::abs(joint.frequencies[k] / joint.frequencies[k - 1] - 1) < 1e-3) ||
                        (k < 11 && std::abs(joint.frequencies[k + 1] / joint.frequencies[k] - 1) < 1e-3);
    if (!paired && nj > 0) {
      EXPECT_NEAR(std::abs(dot) / std::sqrt(nj * na), 1.0, 1e-5) << "mode " << k + 1;
    }
  }
}

// Without a time history the scene's 3D view animates each mode over one period: 24 frames per mode at
// times k + f/24, and at a quarter period the tube is the static shape plus 5 % L times the shape.
TEST(RiserModes, StaticRunAnimatesModeShapesInTheView) {
  RiserParameters p = test::tipLoadedCantilever(10, 0.0);
  p.point_loads.clear();
  RunContext context;
  const Results r = solveRiser(p, context);
  const Table* modes = r.findTable("modes");
  const Table* shapes = r.findTable("mode_shapes");
  ASSERT_NE(modes, nullptr);
  ASSERT_NE(shapes, nullptr);
  const std::size_t count = modes->rows();
  ASSERT_EQ(r.view.frames.size(), 24 * count);
  const Frame3D& quarter = r.view.frames[6];  // mode 1, phase π/2
  EXPECT_NEAR(quarter.time, 0.25, 1e-12);
  // The view shows what a mode frame is, not a time: "mode 1: … rad/s (… Hz), phase 90°".
  EXPECT_EQ(quarter.label.rfind("mode 1: ", 0), 0u) << quarter.label;
  EXPECT_NE(quarter.label.find("phase 90°"), std::string::npos) << quarter.label;
  EXPECT_NE(r.view.frames[24].label.find("mode 2"), std::string::npos) << r.view.frames[24].label;
  const auto& tip = quarter.shapes.front().points.back();
  const int tip_row = p.segment_count + 1;  // mode 1, node n+1
  EXPECT_NEAR(tip.z(), 0.05 * p.length * shapes->find("dz")->values[tip_row], 1e-9);
  EXPECT_NEAR(tip.x(), p.length + 0.05 * p.length * shapes->find("dx")->values[tip_row], 1e-9);
}

// Pinned-pinned pipe conveying fluid (Païdoussis, Fluid-Structure Interactions vol. 1, ch. 3) with
// uniform tension, by the Galerkin solution of riser_references.hpp (`modes` sine modes).
std::vector<double> pipeGalerkin(double length, double m, double fluid, double ei, double tension, double u,
                                 int modes, int count) {
  ConveyingPipe pipe;
  pipe.length = length;
  pipe.mass_per_length = m;
  pipe.fluid_mass_per_length = fluid;
  pipe.ei = ei;
  pipe.top_tension = tension;
  pipe.flow_speed = u;
  return conveyingPipeFrequencies(pipe, modes, count);
}

// The pipe of the tests below: L = 10 m, D 0.1/0.08 m, light wall (ρ = 2000 kg/m³, so the contents are
// 47 % of the mass and the Coriolis coupling is strong), water inside, no gravity, tensioner T, pinned bottom.
RiserParameters fluidConveyingPipe(int n, double tension) {
  RiserParameters p = test::calmInAir();
  p.length = 10.0;
  p.segment_count = n;
  p.outer_diameter = 0.1;
  p.inner_diameter = 0.08;
  p.density = 2000.0;
  p.added_mass_coefficient = 0.0;
  p.internal_fluid_density = 1000.0;
  p.torsion = false;
  p.gravity = 0.0;
  p.top_condition = "tensioner";
  p.top_tension = tension;
  p.bottom_condition = "pinned";
  p.bottom_z = -10.0;
  return p;
}

// Divergence of the pinned-pinned pipe: u_c = √((T + EIπ²/L²)/M) (Païdoussis §3.3; with T = 0 the
// classical (π/L)√(EI/M)). The SM stiffness error is O(1/n²) (eq 66 rows above) and so is the curvature
// fit of the u² term: measured +6.9e-3, +1.9e-3, +5.0e-4 at n = 10, 20, 40. Tolerance 2.5e-3 at n = 20,
// 7e-4 at n = 40, and the error must fall 3 to 5x from n = 20 to 40. Past u_c the state-space solver
// must find unstable pairs (one per bending plane) and lose the first mode.
TEST(RiserModes, PipeConveyingFluidDivergesAtTheClosedFormSpeed) {
  for (double tension : {0.0, 1000.0}) {
    double previous = 0;
    for (int n : {20, 40}) {
      RiserParameters p = fluidConveyingPipe(n, tension);
      const double fluid = p.internal_fluid_density * pi / 4 * 0.0064;
      const double ei = test::bendingStiffness(p), k1 = pi / p.length;
      const double exact = std::sqrt((tension + ei * k1 * k1) / fluid);
      const RiserModel m = buildRiserModel(p);
      RunContext context;
      const StaticSolution s = solveStatics(m, context);
      const double error = divergenceFlowSpeed(m, s) / exact - 1;
      EXPECT_LT(std::abs(error), n == 20 ? 2.5e-3 : 7e-4) << "T = " << tension << " n = " << n;
      if (previous != 0) {
        EXPECT_NEAR(previous / error, 4.0, 1.0) << "T = " << tension;
      }
      previous = error;
      // The run reports it as the scalar divergence_flow_speed (and warns once the flow is beyond it, below).
      RiserParameters run = p;
      run.end_time = 0.0;
      const Results r = solveRiser(run, context);
      ASSERT_NE(r.findScalar("divergence_flow_speed"), nullptr);
      EXPECT_NEAR(r.findScalar("divergence_flow_speed")->value, divergenceFlowSpeed(m, s), 1e-9 * exact);
      if (n == 40) continue;
      p.internal_flow_speed = 1.05 * exact;
      RiserParameters past = p;
      past.end_time = 0.0;
      RunContext warned;
      solveRiser(past, warned);
      const auto notes = warned.warnings();
      EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& w) {
        return w.find("beyond the divergence speed") != std::string::npos;
      })) << "T = " << tension;
      const RiserModel beyond = buildRiserModel(p);
      const RiserModes modes = computeModes(beyond, solveStatics(beyond, context), 4);
      EXPECT_EQ(modes.unstable_count, 2) << "one diverging mode per bending plane, T = " << tension;
      ASSERT_FALSE(modes.frequencies.empty());
      const double second = pipeGalerkin(p.length, fluid + p.density * pi / 4 * 0.0036, fluid, ei, tension,
                                         0.0, 8, 2)[1];
      EXPECT_GT(modes.frequencies[0], 0.3 * second) << "the lowest remaining mode is not the first one";
    }
  }
}

// The default riser (2 MN tensioner, water-filled, bent by its current): u_c² is the smallest positive eigenvalue
// of (−K0, K1), with K1 = (K(U) − K0)/U² from two differenced Jacobians. At U = 1 m/s that difference was mostly
// the Jacobians' noise and gave a spurious 15.3 m/s, which moved to 17.3, 16.1 and 16.3 m/s with the water density
// changed by −2, +2 and +5 × 1e-13 of itself. A straight riser's Rayleigh estimate, √((T̄ + EIπ²/L²)/m_f) with the
// mean effective tension T̄ ≈ 1.8 MN, is about 110 m/s. Checked: (1) the same value to 1e-4 under those density
// changes (measured 113.43 m/s, spread 1.1e-5: the static shape's and the central differences' rounding); (2) independently, the state-space solver with the gyroscopic term (computeModes) at the same static
// shape finds no unstable mode at 0.98 u_c and the diverging pair (one per bending plane, the current breaks the
// symmetry only slightly) at 1.02 u_c.
TEST(RiserModes, DivergenceSpeedOfTheDefaultRiserIsNotDifferencingNoise) {
  RiserParameters p;
  p.end_time = 0.0;
  double reference = 0.0;
  StaticSolution statics;
  for (double change : {0.0, -2e-13, 2e-13, 5e-13}) {
    RiserParameters q = p;
    q.water_density *= 1.0 + change;
    const RiserModel m = buildRiserModel(q);
    RunContext context;
    const StaticSolution s = solveStatics(m, context);
    const double speed = divergenceFlowSpeed(m, s);
    if (change == 0.0) {
      reference = speed;
      statics = s;
      continue;
    }
    EXPECT_NEAR(speed, reference, 1e-4 * reference) << "water density changed by " << change << " of itself";
  }
  EXPECT_GT(reference, 80.0);
  EXPECT_LT(reference, 140.0);
  std::printf("[ measured ] divergence flow speed of the default riser %.6g m/s\n", reference);
  for (double ratio : {0.98, 1.02}) {
    RiserParameters flowing = p;
    flowing.internal_flow_speed = ratio * reference;
    const RiserModes modes = computeModes(buildRiserModel(flowing), statics, 4);
    if (ratio < 1.0) {
      EXPECT_EQ(modes.unstable_count, 0) << ratio;
    } else {
      EXPECT_GE(modes.unstable_count, 1) << ratio;
    }
  }
}

// Frequencies with the Coriolis coupling kept (state-space solve) against the multi-mode Galerkin
// reference above (24 modes; 16 modes differ by < 3e-7), T = 0, at u = 0.5 and 0.8 u_c. Measured SM
// errors (O(1/n²), like eq 66): mode 1 at 0.8 u_c +1.2e-2, +3.4e-3, +8.8e-4 at n = 10, 20, 40; the
// others smaller. Tolerance 5e-3 at n = 20 and 1.2e-3 at n = 40. The coupling is really there: without
// it (the same Galerkin with the gyroscopic matrix dropped) mode 1 at 0.8 u_c is off by more than 1 %.
TEST(RiserModes, PipeConveyingFluidMatchesGyroscopicGalerkin) {
  for (int n : {20, 40}) {
    RiserParameters p = fluidConveyingPipe(n, 0.0);
    const double fluid = p.internal_fluid_density * pi / 4 * 0.0064;
    const double mass = fluid + p.density * pi / 4 * 0.0036;
    const double ei = test::bendingStiffness(p), k1 = pi / p.length;
    const double critical = k1 * std::sqrt(ei / fluid);
    const double tolerance = n == 20 ? 5e-3 : 1.2e-3;
    for (double ratio : {0.5, 0.8}) {
      const double u = ratio * critical;
      p.internal_flow_speed = u;
      const std::vector<double> reference = pipeGalerkin(p.length, mass, fluid, ei, 0.0, u, 24, 2);
      const std::vector<double> coarse = pipeGalerkin(p.length, mass, fluid, ei, 0.0, u, 16, 2);
      for (int k = 0; k < 2; ++k) ASSERT_NEAR(coarse[k], reference[k], 1e-6 * reference[k]) << "Galerkin not converged";
      const std::vector<double> w = distinctFrequencies(p, 2);
      ASSERT_EQ(w.size(), 2u);
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(w[k], reference[k], tolerance * reference[k]) << "mode " << k + 1 << " u/u_c = " << ratio << " n = " << n;
      if (ratio == 0.8) {
        const double uncoupled = k1 * k1 * std::sqrt((ei - fluid * u * u / (k1 * k1)) / mass);
        EXPECT_GT(std::abs(uncoupled - reference[0]), 1e-2 * reference[0]);
      }
    }
  }
}

// The state-space solve in absolute coordinates (6 coordinates per segment, the joints kept by the
// null-space basis) must give the joint-coordinate frequencies of the gyroscopic pipe: same system.
// Central differences leave ~1e-9 relative noise: tolerance 1e-6.
TEST(RiserModes, GyroscopicModesAreTheSameInBothFormulations) {
  RiserParameters p = fluidConveyingPipe(10, 500.0);
  p.internal_flow_speed = 60.0;
  const RiserModel m = buildRiserModel(p);
  RunContext context;
  const StaticSolution s = solveStatics(m, context);
  const RiserModes joint = computeModes(m, s, 6, Formulation::Joint);
  const RiserModes absolute = computeModes(m, s, 6, Formulation::Absolute);
  ASSERT_EQ(joint.frequencies.size(), 6u);
  ASSERT_EQ(absolute.frequencies.size(), 6u);
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(absolute.frequencies[k], joint.frequencies[k], 1e-6 * joint.frequencies[k]) << "mode " << k + 1;
}

}  // namespace
}  // namespace maris::riser
