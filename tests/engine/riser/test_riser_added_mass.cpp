// Tangential (axial) added mass: the coefficient C_at acts on accelerations along the segment axes only, the
// normal C_a across them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "riser/riser_scene.hpp"
#include "riser_test_cases.hpp"
#include "riser_test_support.hpp"
#include "engine/release_only.hpp"

namespace maris::riser {
namespace {

using test::column;

// A 20 m water-filled steel pipe hanging straight down from a pinned top that moves vertically by
// A(1 − cos ωt) (starts at rest, no ramp), weightless (g = 0: no weight, no buoyancy), no drag, free bottom:
// the chain moves as one rigid body along its axis, so the top force is F_z = (m + C_at ρ_w A_out L) a(t),
// m = (ρ_r A_r + ρ_f A_inn) L, a(t) = A ω² cos ωt, whatever the normal C_a.
RiserParameters axiallyShakenPipe(double tangential, double normal) {
  RiserParameters p = test::calmInAir();
  p.length = 20.0;
  p.segment_count = 6;
  p.gravity = 0.0;
  p.water_level = 100.0;  // under water (the added mass acts anyway; this keeps the set-up physical)
  p.seabed_level = -100.0;
  p.added_mass_coefficient = normal;
  p.tangential_added_mass_coefficient = tangential;
  p.motion_amplitude_z = 0.5;
  p.motion_period = 4.0;
  p.motion_phase_z_deg = -90.0;
  p.end_time = 4.0;
  p.integrator = "dopri5";
  p.tolerance = 1e-10;
  p.solve_statics = false;
  p.modes = false;
  return p;
}

// Relative to the largest force, within 1e-9: the motion is exact rigid translation (no joint turns), so only the
// integrator's error on the top coordinate (rtol 1e-10) and round-off remain. Normal C_a changes nothing.
// Under the sanitizers two of the four pairs run, (0, 1) and (0.7, 2): both coefficients still change.
TEST(RiserAddedMass, AxialAccelerationFeelsOnlyTheTangentialAddedMass) {
  for (const double tangential : {0.0, 0.7}) {
    for (const double normal : {1.0, 2.0}) {
      if (::maris::test::kSanitizedBuild && (tangential == 0.0) != (normal == 1.0)) continue;
      const RiserParameters p = axiallyShakenPipe(tangential, normal);
      RunContext context;
      const Results r = solveRiser(p, context);
      const double pi = std::numbers::pi, a_out = pi / 4 * p.outer_diameter * p.outer_diameter;
      const double a_inn = pi / 4 * p.inner_diameter * p.inner_diameter;
      const double mass = (p.density * (a_out - a_inn) + p.internal_fluid_density * a_inn) * p.length;
      const double axial = mass + tangential * p.water_density * a_out * p.length;
      const double w = 2 * pi / p.motion_period, amplitude = p.motion_amplitude_z;
      const auto& t = column(r, "history", "time");
      const auto& fz = column(r, "history", "top_force_z");
      const double scale = axial * amplitude * w * w;
      double worst = 0.0;
      for (std::size_t k = 0; k < t.size(); ++k)
        worst = std::max(worst, std::abs(fz[k] - axial * amplitude * w * w * std::cos(w * t[k])));
      EXPECT_LT(worst, 1e-9 * scale) << "C_at = " << tangential << ", C_a = " << normal << ", scale " << scale;
      EXPECT_GT(t.size(), 10u);
    }
  }
}

// The normal response does not see C_at: the bending frequencies of a straight tensioned riser (the paper's case 3,
// current off) are the same with C_at = 0 and C_at = C_a to 1e-9 relative (the axial motion is second order in the
// bending, so it drops out of the linearisation; measured differences are round-off).
// The scenario's frequency sweeps (more pretensions and segment counts, each with the same C_at) run in the
// Release build only: under the sanitizers the run's own modes carry the check.
TEST(RiserAddedMass, BendingFrequenciesDoNotDependOnTheTangentialAddedMass) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_paper_case3_pretensioned.json");
  p.current_speed_surface = p.current_speed_seabed = 0.0;
  p.segment_count = 20;
  p.modes = true;
  p.end_time = 0.0;
  if (::maris::test::kSanitizedBuild) {
    p.sweep_pretension_ratios.clear();
    p.sweep_segment_counts.clear();
  }
  std::vector<double> frequencies[2];
  for (int k = 0; k < 2; ++k) {
    p.tangential_added_mass_coefficient = k == 0 ? 0.0 : p.added_mass_coefficient;
    RunContext context;
    frequencies[k] = column(solveRiser(p, context), "modes", "angular_frequency");
  }
  ASSERT_EQ(frequencies[0].size(), frequencies[1].size());
  ASSERT_GE(frequencies[0].size(), 4u);
  for (std::size_t i = 0; i < frequencies[0].size(); ++i)
    EXPECT_NEAR(frequencies[0][i], frequencies[1][i], 1e-9 * frequencies[1][i]) << "mode " << i + 1;
}

// With C_at ≠ C_a the segments' kinetic energy ½vᵀKv is anisotropic; the velocity terms of Kirchhoff's equations
// (riser_dynamics.cpp) keep it conservative: a chain swinging down from the horizontal in still water (no drag, no
// damping) keeps its energy to the integrator's tolerance, as the isotropic chain does. Bound: 1e-6 of the energy
// exchanged (DOPRI5, rtol 1e-9); without those terms the balance is off by the power vᵀ(dK/dt)v/2. Under the
// sanitizers the anisotropic chain only (the isotropic one runs in the energy tests of test_riser_dynamics).
TEST(RiserAddedMass, AnisotropicAddedMassConservesEnergy) {
  RiserParameters p = test::builtinParameters("scenarios/riser/riser_swinging_chain.json");
  p.integrator = "dopri5";
  p.tolerance = 1e-9;
  for (const double tangential : {0.0, 1.0}) {
    if (::maris::test::kSanitizedBuild && tangential == 0.0) continue;
    p.tangential_added_mass_coefficient = tangential;
    RunContext context;
    const Results r = solveRiser(p, context);
    const auto& kinetic = column(r, "history", "kinetic_energy");
    const double exchanged = *std::max_element(kinetic.begin(), kinetic.end());
    ASSERT_GT(exchanged, 0.0);
    const auto& balance = column(r, "history", "energy_balance_error");
    double worst = 0.0;
    for (double e : balance) worst = std::max(worst, std::abs(e));
    EXPECT_LT(worst, 1e-6 * exchanged) << "C_at = " << tangential << ", largest kinetic energy " << exchanged;
  }
}

}  // namespace
}  // namespace maris::riser
