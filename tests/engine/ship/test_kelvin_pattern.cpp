// Far-field Kelvin wave pattern: the waves stay inside Kelvin's wedge and have the transverse wavelength.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ship/hull_form.hpp"
#include "ship/kelvin_pattern.hpp"

using namespace maris::ship;

TEST(KelvinPattern, WaveEnergyLiesInsideTheKelvinWedge) {
  // Kelvin (1887): steady ship waves are confined to a wedge of half-angle asin(1/3) = 19.47° behind the
  // ship. Wigley model L = 4 m at Fn 0.35, up to 2 L behind the stern: the mean square elevation inside 17°
  // (from the bow) must exceed that outside 23° by a factor > 4 (outside there are only the decaying Airy
  // tails of the cusps at this finite distance).
  GridKochin k(sampleHull(makeParametricHull(4.0, 0.4, 0.25), 257, 51), false);
  const double U = 0.35 * std::sqrt(9.81 * 4.0);
  const WavePattern w = kelvinWavePattern(k, U, 9.81, 0.0, 8.0, 3.2, 41, 21);
  double inside = 0, outside = 0;
  int n_in = 0, n_out = 0;
  for (Eigen::Index i = 0; i < w.x.size(); ++i)
    for (Eigen::Index j = 0; j < w.y.size(); ++j) {
      const double angle = std::atan2(std::abs(w.y[j]), 4.0 - w.x[i]) * 180.0 / std::numbers::pi;
      const double e2 = w.elevation(i, j) * w.elevation(i, j);
      if (angle < 17.0) {
        inside += e2;
        ++n_in;
      } else if (angle > 23.0) {
        outside += e2;
        ++n_out;
      }
    }
  EXPECT_GT(inside / n_in, 4.0 * outside / n_out);
}

TEST(KelvinPattern, CentrelineWavesHaveTheTransverseWavelength) {
  // Far behind on the track only transverse waves (θ = 0) remain: wavelength 2π U²/g. Count zero crossings of
  // ζ along the centreline between 1 L and 2 L behind the stern: crossings ≈ 2 × distance / wavelength
  // (within one crossing at each end).
  GridKochin k(sampleHull(makeParametricHull(4.0, 0.4, 0.25), 257, 51), false);
  const double U = 0.35 * std::sqrt(9.81 * 4.0), wavelength = 2.0 * std::numbers::pi * U * U / 9.81;
  const WavePattern w = kelvinWavePattern(k, U, 9.81, 0.0, 8.0, 0.5, 161, 3);
  int crossings = 0;
  for (Eigen::Index i = 80; i + 1 < w.x.size(); ++i)
    if (w.elevation(i, 1) * w.elevation(i + 1, 1) < 0) ++crossings;
  const double expected = 2.0 * (w.x[80] - w.x[w.x.size() - 1]) / wavelength;
  EXPECT_NEAR(crossings, expected, 1.5);
}
