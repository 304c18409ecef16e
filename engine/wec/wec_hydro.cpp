#include "wec/wec_hydro.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/angles.hpp"

namespace maris::wec {

namespace {

// Hulme (1982) Table 1, heave, as tabulated in LHEEA/Hulme_Heaving_Sphere comparison/HulmeResult.dat.
// The ka = 0 row is the exact rigid-lid limit.
const std::vector<double> kHeaveKa = {0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2,
                                      1.4, 1.6, 1.8, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0};
const std::vector<double> kHeaveMu = {0.8310, 0.8764, 0.8627, 0.7938, 0.7157, 0.6452, 0.5861, 0.5381, 0.4999,
                                      0.4698, 0.4464, 0.4284, 0.4047, 0.3924, 0.3871, 0.3864, 0.3884, 0.3988,
                                      0.4111, 0.4322, 0.4471, 0.4574, 0.4647, 0.4700, 0.4740, 0.4771};
const std::vector<double> kHeaveLambda = {0.0,    0.1036, 0.1816, 0.2793, 0.3254, 0.3410, 0.3391, 0.3271, 0.3098,
                                          0.2899, 0.2691, 0.2484, 0.2096, 0.1756, 0.1469, 0.1229, 0.1031, 0.0674,
                                          0.0452, 0.0219, 0.0116, 0.0066, 0.0040, 0.0026, 0.0017, 0.0012};

// Hulme (1982) Table 2, surge added mass as transcribed in the source file, with two corrections:
//  * the node printed "3.4" is taken as 3.5, which matches the WAMIT run at ka = 3.22 better;
//  * ka = 0.7 reads 0.6682 there; 0.6582 is used (transposed digits): with 0.6682 the Ogilvie relation
//    returns A∞/(ρV) = 0.2805 at ka = 0.69 against 0.2716 ± 0.0005 at every other ka in [0.03, 5], and the
//    WAMIT run gives μ11 = 0.6597 at ka = 0.665 (0.6650 interpolated from 0.6682, 0.6584 from 0.6582).
// The ka = 0 row is the exact rigid-lid limit.
const std::vector<double> kSurgeMuKa = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2, 1.4, 1.6,
                                        1.8, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0};
const std::vector<double> kSurgeMu = {0.5,    0.5223, 0.5515, 0.5848, 0.6175, 0.6439, 0.6586, 0.6582, 0.6421,
                                      0.6127, 0.5740, 0.4860, 0.4038, 0.3371, 0.2866, 0.2493, 0.1961, 0.1720,
                                      0.1634, 0.1620, 0.1641, 0.1679, 0.1772, 0.1865, 0.1949, 0.2022, 0.2085};
// Surge damping: Hulme Table 2 for ka ≤ 1.4, then WAMIT sphere.out (a = 5 m, B̄11/V at T = 3.5, 3, 2.5,
// 2, 1.5, 1, 0.5 s, i.e. ka = 20.128/T²).
const std::vector<double> kSurgeLambdaKa = {0.0, 0.1,    0.2,    0.3,    0.4,    0.5,    0.6,    0.7,     0.8,
                                            0.9, 1.0,    1.2,    1.4,    1.6431, 2.2365, 3.2205, 5.0320,  8.9459,
                                            20.128, 80.513};
const std::vector<double> kSurgeLambda = {0.0,    0.0010, 0.0082, 0.0255, 0.0557, 0.0987, 0.1516,
                                          0.2092, 0.2653, 0.3145, 0.3535, 0.3978, 0.406,  0.38738,
                                          0.30956, 0.20416, 0.10690, 0.040553, 0.010077, 0.00023510};

// Excitation phases [deg] of the WAMIT hemisphere run (e^{+iωt}, heading 0), versus ka = 20.128/T²,
// unwrapped; ka = 0 is the exact long-wave limit.
const std::vector<double> kPhaseKa = {0.0,    0.0957, 0.1398, 0.2013, 0.2485, 0.3145, 0.4108, 0.4764, 0.5591,
                                      0.6654, 0.8051, 0.9940, 1.2580, 1.6431, 2.2365, 3.2205, 5.0320};
const std::vector<double> kHeavePhaseDeg = {0, 1, 1, 3, 4, 6, 9, 12, 15, 19, 25, 34, 47, 66, 97, 150, 251};
const std::vector<double> kSurgePhaseDeg = {90, 90, 90, 90, 89, 89, 88, 87, 86, 85, 83, 82, 83, 92, 114, 160, 257};

// Beyond the last node: y = limit + (y_n − limit)(ka_n/ka)^p with p from the last two nodes.
double powerTail(const std::vector<double>& ka, const std::vector<double>& y, double limit, double x) {
  const std::size_t n = ka.size();
  const double d1 = y[n - 2] - limit, d2 = y[n - 1] - limit;
  const double p = std::log(d1 / d2) / std::log(ka[n - 1] / ka[n - 2]);
  return limit + d2 * std::pow(ka[n - 1] / x, p);
}

double tabulated(const MonotoneCubic& f, const std::vector<double>& ka, const std::vector<double>& y, double limit,
                 double x) {
  if (x <= 0.0) return y.front();
  if (x >= ka.back()) return powerTail(ka, y, limit, x);
  return f(x);
}

}  // namespace

double hulmeHeaveAddedMass(double ka) {
  static const MonotoneCubic f(kHeaveKa, kHeaveMu);
  return tabulated(f, kHeaveKa, kHeaveMu, HulmeLimits::heave_added_mass_infinity, ka);
}
double hulmeHeaveDamping(double ka) {
  static const MonotoneCubic f(kHeaveKa, kHeaveLambda);
  return tabulated(f, kHeaveKa, kHeaveLambda, 0.0, ka);
}
double hulmeSurgeAddedMass(double ka) {
  static const MonotoneCubic f(kSurgeMuKa, kSurgeMu);
  return tabulated(f, kSurgeMuKa, kSurgeMu, HulmeLimits::surge_added_mass_infinity, ka);
}
double hulmeSurgeDamping(double ka) {
  static const MonotoneCubic f(kSurgeLambdaKa, kSurgeLambda);
  return tabulated(f, kSurgeLambdaKa, kSurgeLambda, 0.0, ka);
}
double hemisphereHeavePhase(double ka) {
  static const MonotoneCubic f(kPhaseKa, kHeavePhaseDeg);
  return f(ka) * kRadiansPerDegree;
}
double hemisphereSurgePhase(double ka) {
  static const MonotoneCubic f(kPhaseKa, kSurgePhaseDeg);
  return f(ka) * kRadiansPerDegree;
}

// ---------------------------------------------------------------------------------------------
HemisphereHydro::HemisphereHydro(double radius, double density, double gravity)
    : radius_(radius), density_(density), gravity_(gravity) {}

double HemisphereHydro::displacedVolume() const { return 2.0 / 3.0 * std::numbers::pi * std::pow(radius_, 3); }

FloatHydro HemisphereHydro::at(double omega) const {
  if (omega <= 0.0) {  // zero-frequency limit: rigid-lid added masses, no damping, no excitation
    const double rho_v = density_ * displacedVolume();
    FloatHydro h;
    h.surge.added_mass = rho_v * HulmeLimits::surge_added_mass_zero;
    h.heave.added_mass = rho_v * HulmeLimits::heave_added_mass_zero;
    return h;
  }
  const double ka = omega * omega * radius_ / gravity_;
  const double rho_v = density_ * displacedVolume();
  const double g3_w3 = std::pow(gravity_ / omega, 3);
  FloatHydro h;
  h.surge.added_mass = rho_v * hulmeSurgeAddedMass(ka);
  h.surge.damping = rho_v * omega * hulmeSurgeDamping(ka);
  h.heave.added_mass = rho_v * hulmeHeaveAddedMass(ka);
  h.heave.damping = rho_v * omega * hulmeHeaveDamping(ka);
  // Haskind–Newman magnitudes with the BEM phases.
  h.surge.excitation = std::polar(std::sqrt(4.0 * density_ * g3_w3 * h.surge.damping), hemisphereSurgePhase(ka));
  h.heave.excitation = std::polar(std::sqrt(2.0 * density_ * g3_w3 * h.heave.damping), hemisphereHeavePhase(ka));
  return h;
}

double HemisphereHydro::addedMassInfinitySurge() const {
  return density_ * displacedVolume() * HulmeLimits::surge_added_mass_infinity;
}
double HemisphereHydro::addedMassInfinityHeave() const {
  return density_ * displacedVolume() * HulmeLimits::heave_added_mass_infinity;
}
// Damping beyond ka = 80 is below 1e-4 of its peak in both modes.
double HemisphereHydro::maxFrequency() const { return std::sqrt(80.0 * gravity_ / radius_); }

std::string HemisphereHydro::describe() const {
  std::ostringstream s;
  s << "floating hemisphere a = " << radius_ << " m, deep water: Hulme (1982) tables, Haskind excitation";
  return s.str();
}

// ---------------------------------------------------------------------------------------------
TabulatedHydro::TabulatedHydro(std::vector<Row> rows, double a_inf_surge, double a_inf_heave, std::string source)
    : rows_(std::move(rows)), a_inf_surge_(a_inf_surge), a_inf_heave_(a_inf_heave), source_(std::move(source)) {
  std::sort(rows_.begin(), rows_.end(), [](const Row& a, const Row& b) { return a.omega < b.omega; });
  std::vector<double> w, ax, az, bx, bz, xrx, xix, xrz, xiz;
  // ω = 0 anchor: damping and excitation vanish, added mass held.
  w.push_back(0.0);
  ax.push_back(rows_.front().hydro.surge.added_mass);
  az.push_back(rows_.front().hydro.heave.added_mass);
  for (auto* v : {&bx, &bz, &xrx, &xix, &xrz, &xiz}) v->push_back(0.0);
  for (const auto& r : rows_) {
    if (r.omega <= w.back()) continue;
    w.push_back(r.omega);
    ax.push_back(r.hydro.surge.added_mass);
    az.push_back(r.hydro.heave.added_mass);
    bx.push_back(r.hydro.surge.damping);
    bz.push_back(r.hydro.heave.damping);
    xrx.push_back(r.hydro.surge.excitation.real());
    xix.push_back(r.hydro.surge.excitation.imag());
    xrz.push_back(r.hydro.heave.excitation.real());
    xiz.push_back(r.hydro.heave.excitation.imag());
  }
  a_x_ = MonotoneCubic(w, ax);
  a_z_ = MonotoneCubic(w, az);
  b_x_ = MonotoneCubic(w, bx);
  b_z_ = MonotoneCubic(w, bz);
  xr_x_ = MonotoneCubic(w, xrx);
  xi_x_ = MonotoneCubic(w, xix);
  xr_z_ = MonotoneCubic(w, xrz);
  xi_z_ = MonotoneCubic(w, xiz);
}

FloatHydro TabulatedHydro::at(double omega) const {
  FloatHydro h;
  h.surge = {a_x_(omega), b_x_(omega), {xr_x_(omega), xi_x_(omega)}};
  h.heave = {a_z_(omega), b_z_(omega), {xr_z_(omega), xi_z_(omega)}};
  return h;
}

double TabulatedHydro::maxFrequency() const { return rows_.back().omega; }

}  // namespace maris::wec
