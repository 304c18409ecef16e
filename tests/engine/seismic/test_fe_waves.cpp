// Wave problems with closed-form or analytic answers, solved by the FE engine with
// boundary-substructure input: half-space surface doubling, the paper's verification box, symmetry.
#include <cstdio>

#include <gtest/gtest.h>

#include "fe_test_support.hpp"
#include "seismic/fe_mesh.hpp"

namespace maris::seismic {
namespace {

using testing::boxParameters;
using testing::peakAbs;
using testing::runDriven;

// Peak of |v| over samples from index `from` on.
double peakFrom(const std::vector<double>& v, std::size_t from) {
  double m = 0.0;
  for (std::size_t k = from; k < v.size(); ++k) m = std::max(m, std::abs(v[k]));
  return m;
}

void expectSurfaceDoubling(WaveType type) {
  // Homogeneous half-space (600 m deep column, no water), vertical incidence, 0.4 s pulse resolved by
  // ≥ 10 cells per shortest wavelength: the free surface moves 2× the incident wave. 1 % covers the
  // dispersion of the discrete wave; after the reflected pulse has left through the bottom, what is
  // left in the model (spurious reflections) must stay below 2 % of that peak.
  const auto p = boxParameters(false, 10.0, 100.0, 600.0);
  const FeMesh mesh = buildMesh(p, false);
  const double arrival = 0.3;  // at the surface; the pulse enters the bottom 600/c earlier
  const auto run = runDriven(p, 0.0, type, 0.4, arrival, 2.0, {mesh.nx / 2, mesh.ny});
  const auto& surface = type == WaveType::P ? run.result.uy[0] : run.result.ux[0];
  EXPECT_NEAR(peakAbs(surface) / 2.0, 1.0, 0.01);
  const double c = type == WaveType::P ? 4500.0 : 1800.0;
  const double gone = arrival + 0.4 + 600.0 / c + 0.2;  // the reflection has left the bottom
  const auto from = static_cast<std::size_t>(gone / run.result.time_step);
  ASSERT_LT(from, surface.size());
  EXPECT_LT(peakFrom(surface, from), 0.02 * 2.0);
  double left_over = 0.0;
  for (double u : run.result.final_state.ux) left_over = std::max(left_over, std::abs(u));
  for (double u : run.result.final_state.uy) left_over = std::max(left_over, std::abs(u));
  EXPECT_LT(left_over, 0.02 * 2.0);
}

TEST(FeWaves, HalfSpaceSurfaceDoublesVerticalP) { expectSurfaceDoubling(WaveType::P); }
TEST(FeWaves, HalfSpaceSurfaceDoublesVerticalSv) { expectSurfaceDoubling(WaveType::SV); }

TEST(FeWaves, VerificationBoxMatchesTheFreeField) {
  // The paper's verification box (§3.4): 1400 m wide, 600 m water over 600 m seabed, P at 45°. The
  // test uses a 0.4 s pulse on a 10 Hz mesh (Δ ≈ 14 m) to stay within the test budget; the bench runs
  // the paper's 0.2 s pulse on the 20 Hz mesh. FE at B (seabed, x = 0) and A (water surface) against
  // the analytic free field: peak error ≤ 3 % and largest pointwise error ≤ 5 % of the peak over 3 s
  // (discretisation of the water reverberation, which rings with reflection 0.78 per round trip).
  const auto p = boxParameters(true, 10.0, 700.0, 600.0);
  const FeMesh mesh = buildMesh(p, true);
  int j_seabed = 0;
  while (mesh.nodeY(j_seabed) < -1e-9) ++j_seabed;
  const auto run = runDriven(p, 45.0, WaveType::P, 0.4, 0.4, 3.0, {mesh.nx / 2, j_seabed, mesh.nx / 2, mesh.ny});
  for (int r = 0; r < 2; ++r) {
    for (int comp = 0; comp < 2; ++comp) {
      if (r == 1 && comp == 0) continue;  // u_x ≡ 0 at the water surface
      const auto& fe = comp == 0 ? run.result.ux[r] : run.result.uy[r];
      const auto& ff = comp == 0 ? run.free_ux[r] : run.free_uy[r];
      const double peak = peakAbs(ff);
      double worst = 0.0;
      for (std::size_t k = 0; k < fe.size(); ++k) worst = std::max(worst, std::abs(fe[k] - ff[k]));
      const char* name = r == 0 ? (comp == 0 ? "B u_x" : "B u_y") : "A u_y";
      EXPECT_NEAR(peakAbs(fe) / peak, 1.0, 0.03) << name;
      EXPECT_LT(worst / peak, 0.05) << name;
    }
  }
}

TEST(FeWaves, VerticalPOnASymmetricReefGivesAMirroredField) {
  // Vertical P on the (symmetric) placeholder reef: u_x(−x) = −u_x(x), u_y(−x) = u_y(x). Only the
  // order of floating-point sums differs between mirrored nodes: 1e-8 of the peak.
  SeismicParameters p;
  p.cutoff_frequency = 1.0;
  const FeMesh mesh = buildMesh(p, true);
  const int j_top = mesh.ny, i_mid = mesh.nx / 2;
  std::vector<int> nodes;
  for (int di : {3, 7, 12}) nodes.insert(nodes.end(), {i_mid - di, j_top - 3, i_mid + di, j_top - 3});
  const auto run = runDriven(p, 0.0, WaveType::P, 1.0, 0.8, 2.5, nodes);
  double scale = 0.0;
  for (const auto& h : run.result.uy) scale = std::max(scale, peakAbs(h));
  ASSERT_GT(scale, 0.1);
  for (std::size_t r = 0; r + 1 < run.result.ux.size(); r += 2) {
    for (std::size_t k = 0; k < run.result.ux[r].size(); ++k) {
      ASSERT_NEAR(run.result.ux[r][k], -run.result.ux[r + 1][k], 1e-8 * scale);
      ASSERT_NEAR(run.result.uy[r][k], run.result.uy[r + 1][k], 1e-8 * scale);
    }
  }
}

}  // namespace
}  // namespace maris::seismic

namespace maris::seismic {
namespace {

TEST(FeWaves, MirroredIncidenceMirrorsTheResponse) {
  // θ → −θ on the symmetric reef: u_x(x, θ) = −u_x(−x, −θ), u_y(x, θ) = u_y(−x, −θ) (1e-8 of the peak).
  SeismicParameters p;
  p.cutoff_frequency = 1.0;
  const FeMesh mesh = buildMesh(p, true);
  const int j = mesh.ny - 2, i_mid = mesh.nx / 2;
  const std::vector<int> right{i_mid + 4, j, i_mid + 9, j}, left{i_mid - 4, j, i_mid - 9, j};
  const auto plus = testing::runDriven(p, 30.0, WaveType::P, 1.0, 0.8, 2.0, right);
  const auto minus = testing::runDriven(p, -30.0, WaveType::P, 1.0, 0.8, 2.0, left);
  double scale = 0.0;
  for (const auto& h : plus.result.ux) scale = std::max(scale, testing::peakAbs(h));
  ASSERT_GT(scale, 0.1);
  for (std::size_t r = 0; r < 2; ++r)
    for (std::size_t k = 0; k < plus.result.ux[r].size(); ++k) {
      ASSERT_NEAR(plus.result.ux[r][k], -minus.result.ux[r][k], 1e-8 * scale);
      ASSERT_NEAR(plus.result.uy[r][k], minus.result.uy[r][k], 1e-8 * scale);
    }
}

}  // namespace
}  // namespace maris::seismic

namespace maris::seismic {
namespace {

TEST(FeWaves, VerificationBoxMatchesTheFreeFieldAtOtherAnglesAndWithoutWater) {
  // The verification-box check (as above, same tolerances: peak 3 %, pointwise 5 % of the peak
  // over 3 s at the seabed B, x = 0) for P 0° and 75°, SV 0° and 20° with water and P 30° without.
  // A 0.4 s pulse on a coarser 7 Hz mesh (Δ ≈ 21 m, ≥ 10 cells per wavelength up to 7 Hz) keeps the
  // five runs inside the test budget.
  struct Row {
    WaveType type;
    double angle;
    bool water;
  };
  for (const Row row : {Row{WaveType::P, 0.0, true}, Row{WaveType::P, 75.0, true}, Row{WaveType::SV, 0.0, true},
                        Row{WaveType::SV, 20.0, true}, Row{WaveType::P, 30.0, false}}) {
    const auto p = testing::boxParameters(row.water, 7.0, 700.0, 600.0);
    const FeMesh mesh = buildMesh(p, row.water);
    int j_seabed = 0;
    while (mesh.nodeY(j_seabed) < -1e-9) ++j_seabed;
    const auto run = testing::runDriven(p, row.angle, row.type, 0.4, 0.6, 3.0, {mesh.nx / 2, j_seabed});
    for (int comp = 0; comp < 2; ++comp) {
      const auto& fe = comp == 0 ? run.result.ux[0] : run.result.uy[0];
      const auto& ff = comp == 0 ? run.free_ux[0] : run.free_uy[0];
      const double peak = testing::peakAbs(ff);
      if (peak < 1e-6) continue;  // u_x of vertical P, u_y of vertical SV: identically zero
      double worst = 0.0;
      for (std::size_t k = 0; k < fe.size(); ++k) worst = std::max(worst, std::abs(fe[k] - ff[k]));
      EXPECT_NEAR(testing::peakAbs(fe) / peak, 1.0, 0.03)
          << toString(row.type) << " " << row.angle << " water " << row.water << " comp " << comp;
      EXPECT_LT(worst / peak, 0.05) << toString(row.type) << " " << row.angle << " water " << row.water << " comp "
                                    << comp;
      std::printf("[ measured ] %s %4.0f deg water %d u_%c: peak ratio %.4f, pointwise %.4f\n", toString(row.type),
                  row.angle, row.water, comp == 0 ? 'x' : 'y', testing::peakAbs(fe) / peak, worst / peak);
    }
  }
}

}  // namespace
}  // namespace maris::seismic

#include <bit>

#include "seismic/seismic_solve.hpp"

namespace maris::seismic {
namespace {

TEST(FeWaves, WaterLayerResonatesAtTheQuarterWaveFrequency) {
  // Vertical P under 600 m of water on the box (1400 m wide, 600 m seabed), 1 s pulse, 30 s
  // of ringing on a coarse mesh (f_cut 3 Hz, Δ ≈ 48 m: > 40 cells per water wavelength at 0.6 Hz).
  // The Fourier ratio |u_A|/|u_B| (water surface over seabed, x = 0) peaks at the water column's
  // quarter-wave frequency c_f/(4h) = 0.6042 Hz, where the free-field seabed stands still: peak within
  // 2 % (0.012 Hz; the zero-padded spectrum's bins are ≈ 0.005 Hz) and above 10 (closed form: unbounded).
  const auto p = testing::boxParameters(true, 3.0, 700.0, 600.0);
  const FeMesh mesh = buildMesh(p, true);
  int j_seabed = 0;
  while (mesh.nodeY(j_seabed) < -1e-9) ++j_seabed;
  const auto run =
      testing::runDriven(p, 0.0, WaveType::P, 1.0, 0.5, 30.0, {mesh.nx / 2, j_seabed, mesh.nx / 2, mesh.ny});
  const double dt = run.result.time_step;
  const std::size_t n_fft = 4 * std::bit_ceil(run.result.uy[0].size());
  const auto b = fourierAmplitude(run.result.uy[0], dt, n_fft), a = fourierAmplitude(run.result.uy[1], dt, n_fft);
  double best = 0.0, f_best = 0.0;
  for (std::size_t k = 1; k < b.size(); ++k) {
    const double f = k / (n_fft * dt);
    if (f < 0.3 || f > 1.0) continue;
    if (a[k] / b[k] > best) best = a[k] / b[k], f_best = f;
  }
  const double f1 = 1450.0 / (4.0 * 600.0);
  std::printf("[ measured ] |u_A|/|u_B| peaks at %.4f Hz (c_f/4h = %.4f Hz) with %.1f\n", f_best, f1, best);
  EXPECT_NEAR(f_best / f1, 1.0, 0.02);
  EXPECT_GT(best, 10.0);
}

}  // namespace
}  // namespace maris::seismic
