// Float–float hydrodynamic interaction from multi-body Nemoh files (the coupled frequency domain is derived here; not in the paper).
// Synthetic two-body files with a coupling whose effect is known in closed form: two identical floats whose
// radiation matrices are A = A_1 ⊗ [[1, c], [c, 1]] (same for B) and whose excitations are equal (or opposite)
// move in the symmetric (antisymmetric) mode θ_1 = ±θ_2, in which each float behaves exactly as a single float with
// coefficients scaled by (1 ± c). The single-float reference runs through the ordinary one-body import.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

#include "core/errors.hpp"
#include "wec/wec_frequency.hpp"
#include "wec/wec_nemoh.hpp"
#include "wec/wec_response.hpp"
#include "wec/wec_time.hpp"
#include "wec_test_models.hpp"

using namespace maris::wec;
namespace fs = std::filesystem;

namespace {
using wec_test::kDeg, wec_test::num, wec_test::scratch;
constexpr double kCoupling = 0.3;  // c

// One frequency row of a multi-body file: A, B (2N×2N over surge/heave of every body) and X (2N, e^{+iωt}).
struct BodyRow {
  double omega;
  Eigen::MatrixXd a, b;
  Eigen::VectorXcd x;
};

// Nemoh layout for N bodies: zones "Motion of body b in DoF d" (d = 1..6), rows of 6N (A, B) pairs body-major;
// excitation (|F|, angle) pairs in e^{−iωt}. Unused DoFs hold distinct junk so a wrong column shows.
void writeBodies(const fs::path& dir, const std::vector<BodyRow>& rows) {
  const int n = static_cast<int>(rows.front().x.size()) / 2;
  auto ours = [](int d) { return d == 1 ? 0 : d == 3 ? 1 : -1; };
  std::ofstream rad(dir / "RadiationCoefficients.tec");
  rad << "VARIABLES=\"w (rad/s)\"\n";
  for (int b = 1; b <= n; ++b)
    for (int d = 1; d <= 6; ++d) {
      rad << "Zone t=\"Motion of body    " << b << " in DoF    " << d << "\",I=  " << rows.size() << ",F=POINT\n";
      for (const auto& r : rows) {
        rad << num(r.omega);
        for (int c = 1; c <= n; ++c)
          for (int e = 1; e <= 6; ++e) {
            const bool used = ours(d) >= 0 && ours(e) >= 0;
            const int i = 2 * (c - 1) + ours(e), j = 2 * (b - 1) + ours(d);
            rad << (used ? num(r.a(i, j)) + num(r.b(i, j)) : num(1e9 + 10 * d + e) + num(-1e9 - e));
          }
        rad << "\n";
      }
    }
  std::ofstream exc(dir / "ExcitationForce.tec");
  exc << "VARIABLES=\"w (rad/s)\"\n";
  exc << "Zone t=\"Diffraction force - beta =    0.0 deg\",I=  " << rows.size() << ",F=POINT\n";
  for (const auto& r : rows) {
    exc << num(r.omega);
    for (int c = 1; c <= n; ++c)
      for (int e = 1; e <= 6; ++e) {
        const Complex x = ours(e) >= 0 ? toEMinusIwt(r.x[2 * (c - 1) + ours(e)]) : Complex(7e8, 0.5);
        exc << num(std::abs(x)) + num(std::arg(x));
      }
    exc << "\n";
  }
}

// Hulme hemisphere (a = 3 m) on 0.1–6 rad/s as the one-body coefficients; `bodies` copies coupled by
// (coupling) in each mode, excitation of body k multiplied by sign^k, everything scaled by `scale`.
std::vector<BodyRow> table(int bodies, double coupling, double sign, double scale,
                           const std::vector<double>& location_x = {}) {
  const HemisphereHydro hulme(3.0, 1025.0, 9.81);
  std::vector<BodyRow> rows;
  for (int k = 0; k < 60; ++k) {
    const double w = 0.1 + 0.1 * k;
    const FloatHydro h = hulme.at(w);
    BodyRow r{w, Eigen::MatrixXd::Zero(2 * bodies, 2 * bodies), Eigen::MatrixXd::Zero(2 * bodies, 2 * bodies),
              Eigen::VectorXcd::Zero(2 * bodies)};
    for (int i = 0; i < bodies; ++i) {
      const Complex phase = location_x.empty() ? Complex(1.0) : std::polar(1.0, -w * w / 9.81 * location_x[static_cast<std::size_t>(i)]);
      r.x[2 * i] = scale * std::pow(sign, i) * h.surge.excitation * phase;
      r.x[2 * i + 1] = scale * std::pow(sign, i) * h.heave.excitation * phase;
      for (int j = 0; j < bodies; ++j) {
        const double f = scale * (i == j ? 1.0 : coupling);
        r.a(2 * i, 2 * j) = f * h.surge.added_mass;
        r.a(2 * i + 1, 2 * j + 1) = f * h.heave.added_mass;
        r.b(2 * i, 2 * j) = f * h.surge.damping;
        r.b(2 * i + 1, 2 * j + 1) = f * h.heave.damping;
      }
    }
    rows.push_back(r);
  }
  return rows;
}

WecParameters twoFloats(const fs::path& dir) {
  WecParameters p = wec_test::defaults();
  p.hydro_source = "nemoh_files";
  p.nemoh_directory = dir.string();
  p.floats.push_back(p.floats.front());
  p.floats[1].hinge_x = 20.0;
  return p;
}
// One float centred at x = 0, where the one-body import's location phase e^{−ikx_f} is 1, as in the synthetic
// multi-body excitation.
WecParameters oneFloat(const fs::path& dir) {
  WecParameters p = wec_test::defaults();
  p.hydro_source = "nemoh_files";
  p.nemoh_directory = dir.string();
  p.floats[0].hinge_x = -p.floats[0].arm_length * std::cos(p.floats[0].arm_angle_deg * kDeg);
  return p;
}
}  // namespace

// Frequency domain: in the symmetric mode (equal excitation) each coupled float has the RAO and hinge forces of a
// single float with coefficients ×(1 + c); in the antisymmetric mode (opposite excitation) ×(1 − c), with θ_2 = −θ_1.
// Both are linear algebra on the same tables, so they agree to round-off (1e-9).
TEST(WecCoupled, SymmetricAndAntisymmetricModesMatchScaledSingleFloat) {
  for (double sign : {1.0, -1.0}) {
    const fs::path pair = scratch(sign > 0 ? "sym_pair" : "anti_pair"), single = scratch(sign > 0 ? "sym_one" : "anti_one");
    writeBodies(pair, table(2, kCoupling, sign, 1.0));
    auto scaled = table(1, 0.0, 1.0, 1.0 + sign * kCoupling);
    for (auto& r : scaled) r.x /= 1.0 + sign * kCoupling;  // excitation is not scaled
    writeBodies(single, scaled);
    const WecModel coupled = buildWecModel(twoFloats(pair)), reference = buildWecModel(oneFloat(single));
    ASSERT_TRUE(coupled.coupled);
    for (double w = 0.3; w <= 3.0; w += 0.1) {
      const FrequencyResponse ref = solveFrequency(reference, reference.floats[0], w);
      const FrequencyResponse f1 = solveFrequency(coupled, coupled.floats[0], w);
      const FrequencyResponse f2 = solveFrequency(coupled, coupled.floats[1], w);
      EXPECT_NEAR(std::abs(f1.pitch - ref.pitch), 0.0, 1e-9 * std::abs(ref.pitch)) << "omega " << w;
      EXPECT_NEAR(std::abs(f2.pitch - sign * ref.pitch), 0.0, 1e-9 * std::abs(ref.pitch)) << "omega " << w;
      EXPECT_NEAR(std::abs(f1.hinge_fz - ref.hinge_fz), 0.0, 1e-9 * std::abs(ref.hinge_fz)) << "omega " << w;
      EXPECT_NEAR(std::abs(f1.hinge_fx - ref.hinge_fx), 0.0, 1e-9 * std::abs(ref.hinge_fx)) << "omega " << w;
    }
  }
}

// With zero cross terms and each body's excitation carrying its location phase e^{−ikx_f}, the coupled path gives
// the independent floats of the one-body import (location phase applied by the scene) to round-off: the two
// conventions for where the phase lives agree.
TEST(WecCoupled, ZeroCouplingEqualsIndependentFloats) {
  const fs::path pair = scratch("zero_pair"), single = scratch("zero_one");
  const WecParameters p = twoFloats(pair);
  std::vector<double> x;
  for (const auto& f : p.floats) x.push_back(f.hinge_x + f.arm_length * std::cos(f.arm_angle_deg * kDeg));
  writeBodies(pair, table(2, 0.0, 1.0, 1.0, x));
  writeBodies(single, table(1, 0.0, 1.0, 1.0));
  WecParameters q = p;
  q.nemoh_directory = single.string();
  const WecModel coupled = buildWecModel(p), independent = buildWecModel(q);
  ASSERT_TRUE(coupled.coupled);
  ASSERT_FALSE(independent.coupled);
  for (double w = 0.3; w <= 3.0; w += 0.3)
    for (std::size_t i = 0; i < 2; ++i) {
      const Complex a = solveFrequency(coupled, coupled.floats[i], w).pitch;
      const Complex b = solveFrequency(independent, independent.floats[i], w).pitch;
      EXPECT_NEAR(std::abs(a - b), 0.0, 1e-9 * std::abs(b)) << "omega " << w << " float " << i;
    }
}

// Time domain with the cross kernels (state-space fits of K_12 = c K_11 in each mode): the steady response of both
// floats (H = 0.1 m) matches the coupled frequency domain within 1.5 % and 2°, in the classical RK4 and
// the augmented Newmark formulations, and the energy balance over both floats closes within 1 %:
// radiated power includes what each float's motion does against the other's radiation.
TEST(WecCoupled, TimeDomainMatchesCoupledFrequencyDomain) {
  const fs::path pair = scratch("td_pair");
  writeBodies(pair, table(2, kCoupling, -1.0, 1.0));
  const WecModel m = wec_test::model(twoFloats(pair));
  EXPECT_EQ(m.cross.size(), 4u);  // (surge 1, surge 2), (heave 1, heave 2), both ways; surge–heave terms are 0
  double r2 = 1.0;
  for (const auto& c : m.cross) {
    EXPECT_TRUE(c.mode.fit.stable());
    r2 = std::min(r2, c.mode.fit.r_squared);
  }
  RecordProperty("cross_fit_r2_min", std::to_string(r2));
  double worst_amp = 0.0, worst_phase = 0.0, worst_balance = 0.0;
  for (bool augmented : {false, true}) {
    TimeDomainOptions o;
    o.augmented = augmented;
    o.newmark = augmented;
    for (double w : {0.8, 1.4}) {
      const SteadyResponse s = steadyResponse(m, w, 0.1, 30.0, o, 10, nullptr);
      double exc = 0.0, out = 0.0;
      for (std::size_t i = 0; i < 2; ++i) {
        const FrequencyResponse fd = solveFrequency(m, m.floats[i], w);
        worst_amp = std::max(worst_amp, std::abs(std::abs(s.pitch[i]) / std::abs(fd.pitch) - 1.0));
        worst_phase = std::max(worst_phase, std::abs(std::arg(s.pitch[i] / fd.pitch)) / kDeg);
        EXPECT_NEAR(std::abs(s.pitch[i]) / std::abs(fd.pitch), 1.0, 0.015) << w << " float " << i << " " << augmented;
        EXPECT_NEAR(std::arg(s.pitch[i] / fd.pitch), 0.0, 2.0 * kDeg) << w << " float " << i << " " << augmented;
        exc += s.excitation_power[i];
        out += s.pto_power[i] + s.radiated_power[i];
      }
      worst_balance = std::max(worst_balance, std::abs(out / exc - 1.0));
      EXPECT_NEAR(out / exc, 1.0, 0.01) << w << " " << augmented;
    }
  }
  RecordProperty("worst", std::to_string(worst_amp) + " " + std::to_string(worst_phase) + " deg, balance " +
                              std::to_string(worst_balance));
}

// A two-body file with three floats, or with waves along −x (heading 180 is not read), is an input error naming
// the field.
TEST(WecCoupled, MismatchedFloatsAreInputErrors) {
  const fs::path pair = scratch("bad_pair");
  writeBodies(pair, table(2, kCoupling, 1.0, 1.0));
  WecParameters p = twoFloats(pair);
  p.floats.push_back(p.floats.front());
  p.floats[2].hinge_x = 40.0;
  try {
    buildWecModel(p);
    FAIL() << "expected InputError";
  } catch (const maris::InputError& e) {
    EXPECT_EQ(e.errors().front().path, "floats") << e.what();
  }
  p = twoFloats(pair);
  p.wave_direction = "-x";
  EXPECT_THROW(buildWecModel(p), maris::InputError);
}
