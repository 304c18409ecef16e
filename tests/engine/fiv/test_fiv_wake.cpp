// The VIV sub-model against Facchinetti, de Langre & Biolley (2004, JFS 19:123–140) with their
// published circular-cylinder parameters: St = 0.2, ε = 0.3, A = 12, C_L0 = 0.3, ξ = 3.1e-3, μ = 250.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/run_context.hpp"
#include "fiv/fiv_sweep.hpp"
#include "fiv_test_support.hpp"

namespace maris::fiv {
namespace {

FivParameters facchinettiCircular() {
  FivParameters p;
  p.forcing = "viv";
  p.side = 0.1;
  p.length = 1.0;
  p.density = 1000.0;
  p.added_mass_coefficient = 0.0;  // μ = (m_s + m_f)/(ρD²) already includes the fluid mass
  p.mass = 250.0 * p.density * p.side * p.side * p.length;
  p.stiffness = p.mass * std::pow(2.0 * std::numbers::pi, 2);  // f_n = 1 Hz
  p.damping_input = "ratio";
  p.damping_ratio = 3.1e-3;
  p.strouhal = 0.2;
  p.wake_epsilon = 0.3;
  p.wake_coupling = 12.0;
  p.wake_lift_amplitude = 0.3;
  return p;
}

TEST(FivWake, FixedCylinderWakeOscillatesWithAmplitudeTwoAtTheStrouhalFrequency) {
  // Rigid body (m_t = 1e12 kg): q obeys van der Pol, q̈ + εΩ(q² − 1)q̇ + Ω²q = 0, whose limit cycle has
  // amplitude 2 and frequency Ω(1 − ε²/16 + O(ε⁴)) (Lindstedt–Poincaré): within 1 % of 2 and St U/D.
  FivParameters p = facchinettiCircular();
  p.mass = 1e12;
  const FivModel model = buildFivModel(p);
  const double speed = 0.5;
  const FivRhs rhs(model, makeOperatingPoint(model, speed, kDeep));
  const double f_shed = p.strouhal * speed / p.side, h = 1.0 / (200.0 * f_shed);
  State s{0, 0, 0.1, 0, 0, 0};
  double q_max = 0.0, last_up = -1.0, first_up = -1.0, t = 0.0;
  int ups = 0;
  for (int i = 0; i < 200 * 300; ++i) {
    const State prev = s;
    rhs.step(s, h);
    t += h;
    if (i > 200 * 250) q_max = std::max(q_max, s[2]);
    if (i > 200 * 200 && prev[2] < 0.0 && s[2] >= 0.0) {
      const double t_up = t - h * s[2] / (s[2] - prev[2]);
      if (first_up < 0.0) first_up = t_up;
      last_up = t_up;
      ++ups;
    }
  }
  EXPECT_NEAR(q_max, 2.0, 0.02);
  const double f_wake = (ups - 1) / (last_up - first_up);
  EXPECT_NEAR(f_wake / f_shed, 1.0, 0.01);
}

TEST(FivWake, ResponseLocksOntoTheNaturalFrequencyNearReducedVelocityOneOverSt) {
  // Facchinetti et al. (2004) figs 5–7: around U_r = U/(f_n D) = 1/St = 5 the response frequency stays at
  // f_n (lock-in, ±5 %); well outside (U_r = 3 and 9) it follows the Strouhal law f = St U/D (±5 %).
  const FivParameters p = facchinettiCircular();
  const FivModel model = buildFivModel(p);
  SweepSettings settings;
  settings.speeds = {0.3, 0.5, 0.55, 0.9};
  settings.submergence_ratios = {kDeep};
  settings.sweep_down = false;
  settings.seed_amplitude_ratio = 1e-5;
  settings.cycle.max_cycles = 1200;
  settings.cycle.tolerance = 1e-4;
  RunContext ctx;
  const SweepResult sweep = runSweep(model, settings, ctx);
  const auto& up = sweep.branches[0].up;
  auto strouhal = [&](double u) { return p.strouhal * u / p.side; };
  EXPECT_NEAR(up[0].frequency / strouhal(0.3), 1.0, 0.05) << "U_r = 3";
  EXPECT_NEAR(up[1].frequency / model.f_n, 1.0, 0.05) << "U_r = 5";
  EXPECT_NEAR(up[2].frequency / model.f_n, 1.0, 0.05) << "U_r = 5.5";
  EXPECT_NEAR(up[3].frequency / strouhal(0.9), 1.0, 0.05) << "U_r = 9";
  // Lock-in amplifies: the lock-in amplitudes exceed the off-resonance ones by an order of magnitude.
  EXPECT_GT(up[1].amplitude, 10.0 * up[0].amplitude);
  EXPECT_GT(up[1].amplitude, 10.0 * up[3].amplitude);
}

}  // namespace
}  // namespace maris::fiv
