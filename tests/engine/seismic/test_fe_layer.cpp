// 1D SV resonance of a soft layer over a half-space, by the FE engine on a periodic column with a
// Lysmer (dashpot) bottom driven by F = 2ρc·v_incident (exact 1D input for a dashpot boundary).
// Reference (closed form of an elastic layer on an elastic half-space, vertical incidence):
// |u_surface/u_outcrop| = 1/|cos kH + iα sin kH|, k = ω/v₁,
// α = ρ₁v₁/(ρ₂v₂): peaks at f₁ = v₁/(4H) with value 1/α.
#include <complex>
#include <numbers>

#include <gtest/gtest.h>

#include "fe_test_support.hpp"
#include "core/spectrum.hpp"

namespace maris::seismic {
namespace {

TEST(FeLayer, SoftLayerResonatesAtQuarterWavelength) {
  // Δ = 5 m: 48 cells per wavelength in the layer at f₁, so dispersion shifts f₁ by far less than 2 %.
  auto p = testing::boxParameters(false, 36.0, 10.0, 100.0);
  FeMesh mesh = buildMesh(p, false);
  ASSERT_NEAR(mesh.delta, 5.0, 1e-9);
  mesh.periodic_x = true;
  const double layer_thickness = 60.0, v1 = 600.0, rho1 = 2000.0;
  mesh.solids.push_back({rho1, 1200.0, v1});
  for (int j = 0; j < mesh.ny; ++j)
    if (mesh.nodeY(j) >= -layer_thickness - 1e-9)
      for (int i = 0; i < mesh.nx; ++i) mesh.cell_material[j * mesh.nx + i] = 1;
  FeModel model = buildFeModel(mesh);
  // Pure dashpot bottom (no springs): the 1D radiation condition.
  std::fill(model.spring_x.begin(), model.spring_x.end(), 0.0);
  std::fill(model.spring_y.begin(), model.spring_y.end(), 0.0);

  const double dt = 0.8 * model.stable_step, duration = 6.0, pulse = 0.25, start = 0.1;
  const long steps = static_cast<long>(duration / dt);
  auto incident_velocity = [&](double t) {  // derivative of the B-spline pulse by central difference
    const double h = 1e-6;
    return (bsplinePulse(t - start + h, pulse) - bsplinePulse(t - start - h, pulse)) / (2 * h);
  };
  FeRunSettings s;
  s.time_step = dt;
  s.steps = steps;
  s.record_nodes = {mesh.node(0, mesh.ny)};
  s.extra_solid_forces = [&](long n, std::vector<double>& fx, std::vector<double>&) {
    for (int i = 0; i < mesh.nx; ++i) {
      const int a = mesh.node(i, 0);
      fx[a] += 2.0 * model.dashpot_x[a] * incident_velocity(n * dt);
    }
  };
  RunContext ctx;
  const auto run = runExplicit(model, nullptr, FeState::zero(mesh.nodeCount()), s, ctx);

  // Spectral ratio surface / (2 × incident), zero-padded for a fine frequency grid.
  const std::size_t n_fft = 1 << 18;
  std::vector<std::complex<double>> surf(n_fft, 0.0), inc(n_fft, 0.0);
  for (long n = 0; n <= steps; ++n) {
    surf[n] = run.ux[0][n];
    inc[n] = bsplinePulse(n * dt - start, pulse);
  }
  surf = fft(std::move(surf));
  inc = fft(std::move(inc));
  const double df = 1.0 / (n_fft * dt);
  double best_f = 0.0, best = 0.0;
  for (std::size_t k = static_cast<std::size_t>(1.0 / df); k * df < 4.0; ++k) {
    const double r = std::abs(surf[k]) / (2.0 * std::abs(inc[k]));
    if (r > best) best = r, best_f = k * df;
  }
  const double alpha = rho1 * v1 / (p.seabed_density * p.seabed_vs);
  RecordProperty("resonance_over_quarter_wave", std::to_string(best_f / (v1 / (4.0 * layer_thickness))));
  RecordProperty("peak_times_alpha", std::to_string(best * alpha));
  EXPECT_NEAR(best_f / (v1 / (4.0 * layer_thickness)), 1.0, 0.02);
  EXPECT_NEAR(best * alpha, 1.0, 0.05);
}

}  // namespace
}  // namespace maris::seismic
