// Explicit FE engine (fe_model, fe_drive, fe_solver): patch tests, linearity, stability, and wave
// problems with closed-form answers.
#include <random>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "fe_test_support.hpp"

namespace maris::seismic {
namespace {

using testing::boxParameters;
using testing::peakAbs;
using testing::runDriven;

TEST(FeEngine, LinearDisplacementPassesThePatchTest) {
  // Constant strain: interior nodes are in equilibrium, top-surface nodes carry −σ·n·Δ (exact for
  // bilinear elements; round-off 1e-12 of the nodal force scale G·ε·Δ).
  const FeModel model = buildFeModel(buildMesh(boxParameters(false, 2.0, 200.0, 300.0), false));
  const FeMesh& m = model.mesh;
  const double exx = 1e-4, eyy = -3e-4, gxy = 2e-4;  // u = (exx x + gxy y, eyy y)
  std::vector<double> ux(m.nodeCount()), uy(m.nodeCount()), fx(m.nodeCount(), 0.0), fy(m.nodeCount(), 0.0);
  for (int j = 0; j <= m.ny; ++j)
    for (int i = 0; i <= m.nx; ++i) {
      ux[m.node(i, j)] = exx * m.nodeX(i) + gxy * m.nodeY(j);
      uy[m.node(i, j)] = eyy * m.nodeY(j);
    }
  addSolidInternalForces(model, model.solid_cells, ux, uy, fx, fy);
  const ElasticMaterial& s = m.solids[0];
  const double lambda = s.lameLambda(), mu = s.shearModulus();
  const double syy = lambda * (exx + eyy) + 2 * mu * eyy, sxy = mu * gxy;
  const double scale = mu * 1e-4 * m.delta;
  for (int j = 1; j <= m.ny; ++j)
    for (int i = 1; i < m.nx; ++i) {
      const int a = m.node(i, j);
      const double ex = j == m.ny ? -sxy * m.delta : 0.0, ey = j == m.ny ? -syy * m.delta : 0.0;
      ASSERT_NEAR(fx[a], ex, 1e-12 * scale) << i << "," << j;
      ASSERT_NEAR(fy[a], ey, 1e-12 * scale) << i << "," << j;
    }
}

TEST(FeEngine, LinearPotentialPassesThePatchTest) {
  // Constant water velocity potential gradient: no net flux into interior water nodes.
  const FeModel model = buildFeModel(buildMesh(boxParameters(true, 2.0, 200.0, 100.0), true));
  const FeMesh& m = model.mesh;
  std::vector<double> phi(m.nodeCount()), f(m.nodeCount(), 0.0);
  for (int j = 0; j <= m.ny; ++j)
    for (int i = 0; i <= m.nx; ++i) phi[m.node(i, j)] = 0.3 * m.nodeX(i) - 0.7 * m.nodeY(j);
  addWaterInternalForces(model, model.water_cells, phi, f);
  int checked = 0;
  for (int j = 0; j <= m.ny; ++j)
    for (int i = 1; i < m.nx; ++i) {
      const int a = m.node(i, j);
      if (m.nodeY(j) <= 0.0 || model.water_fixed[a]) continue;
      ASSERT_NEAR(f[a], 0.0, 1e-12) << i << "," << j;
      ++checked;
    }
  EXPECT_GT(checked, 10);
}

TEST(FeEngine, ResponseIsLinearInTheInput) {
  // Doubling the incident amplitude doubles every state entry (round-off 1e-12).
  const auto p = boxParameters(true, 4.0, 300.0, 300.0);
  const auto one = runDriven(p, 30.0, WaveType::P, 0.5, 0.4, 0.8, {0, 0}, 1.0);
  const auto two = runDriven(p, 30.0, WaveType::P, 0.5, 0.4, 0.8, {0, 0}, 2.0);
  const auto& a = one.result.final_state;
  const auto& b = two.result.final_state;
  const double scale = peakAbs(b.ux) + peakAbs(b.uy);
  ASSERT_GT(scale, 0.0);
  for (std::size_t k = 0; k < a.ux.size(); ++k) {
    ASSERT_NEAR(b.ux[k], 2 * a.ux[k], 1e-12 * scale);
    ASSERT_NEAR(b.phi[k], 2 * a.phi[k], 1e-12 * (peakAbs(b.phi) + 1e-300));
  }
}

TEST(FeEngine, StepAboveTheStableBoundIsRefused) {
  const FeModel model = buildFeModel(buildMesh(boxParameters(true, 2.0, 200.0, 200.0), true));
  FeRunSettings s;
  s.time_step = 1.01 * model.stable_step;
  s.steps = 10;
  RunContext ctx;
  try {
    runExplicit(model, nullptr, FeState::zero(model.mesh.nodeCount()), s, ctx);
    FAIL() << "an unstable step was accepted";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("exceeds the stable step"), std::string::npos) << e.what();
  }
}

// Random initial displacement and potential in a small closed-off box with water.
FeState randomState(const FeModel& model) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  FeState s = FeState::zero(model.mesh.nodeCount());
  for (int a = 0; a < model.mesh.nodeCount(); ++a) {
    if (model.solid_mass[a] > 0) s.ux[a] = u(rng), s.uy[a] = u(rng);
    if (model.water_mass[a] > 0 && !model.water_fixed[a]) s.phi[a] = 1e3 * u(rng);
  }
  return s;
}

TEST(FeEngine, NinetyPercentOfTheStableStepStaysBounded) {
  // 1e5 steps from a random (all-frequency) state at 0.9 × the element bound, water coupled: the
  // absorbing boundaries only remove energy, so no displacement may exceed its initial maximum.
  const FeModel model = buildFeModel(buildMesh(boxParameters(true, 1.5, 200.0, 200.0), true));
  ASSERT_LT(model.mesh.cellCount(), 200);
  FeRunSettings s;
  s.time_step = 0.9 * model.stable_step;
  s.steps = 100000;
  RunContext ctx;
  const FeState start = randomState(model);
  const auto r = runExplicit(model, nullptr, start, s, ctx);
  EXPECT_LE(peakAbs(r.final_state.ux), peakAbs(start.ux));
  EXPECT_LE(peakAbs(r.final_state.uy), peakAbs(start.uy));
}

TEST(FeEngine, UnstableStepStopsWithADivergenceError) {
  // At 1.5 × the bound (past the true limit) the highest mode grows; the run must stop with a
  // SolverError naming a node, never return NaNs.
  const FeModel model = buildFeModel(buildMesh(boxParameters(true, 1.5, 200.0, 200.0), true));
  FeRunSettings s;
  s.time_step = 1.5 * model.stable_step;
  s.steps = 200000;
  s.enforce_stable_step = false;
  RunContext ctx;
  try {
    runExplicit(model, nullptr, randomState(model), s, ctx);
    FAIL() << "the unstable run finished";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
    EXPECT_GT(e.step(), 0);
  }
}

}  // namespace
}  // namespace maris::seismic
