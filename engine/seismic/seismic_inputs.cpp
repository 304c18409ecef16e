#include "seismic/seismic_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include <Eigen/Dense>

#include "core/checked_count.hpp"
#include "core/errors.hpp"
#include "core/resources.hpp"

namespace maris::seismic {

double bsplinePulse(double t, double duration) {
  const double tau = t / duration;
  auto cube = [](double s) { return s > 0.0 ? s * s * s : 0.0; };
  return 16.0 * (cube(tau) - 4.0 * cube(tau - 0.25) + 6.0 * cube(tau - 0.5) - 4.0 * cube(tau - 0.75) + cube(tau - 1.0));
}

double rickerWavelet(double t, double peak_frequency, double centre) {
  const double a = std::numbers::pi * peak_frequency * (t - centre);
  return (1.0 - 2.0 * a * a) * std::exp(-a * a);
}

namespace {

// Trapezoidal running integral on a uniform grid, starting from 0.
std::vector<double> integrate(const std::vector<double>& f, double dt) {
  std::vector<double> out(f.size(), 0.0);
  for (std::size_t k = 1; k < f.size(); ++k) out[k] = out[k - 1] + 0.5 * dt * (f[k - 1] + f[k]);
  return out;
}

}  // namespace

Accelerogram correctAccelerogram(const std::vector<double>& time, const std::vector<double>& acceleration, double dt,
                                 double peak_acceleration, const std::string& field) {
  if (time.size() < 8 || time.size() != acceleration.size())
    throw InputError(field, std::to_string(time.size()) + " rows", "an accelerogram needs at least 8 (time, acceleration) rows");
  for (std::size_t k = 1; k < time.size(); ++k)
    if (!(time[k] > time[k - 1]))
      throw InputError(field, "row " + std::to_string(k + 1), "time must increase strictly from row to row");

  // Linear resampling onto t_k = k·dt from the record's first time.
  const double duration = time.back() - time.front();
  const std::size_t n =
      static_cast<std::size_t>(checkedCount(std::floor(duration / dt), kMaxStoredSamples, field, "samples of the record")) + 1;
  Accelerogram rec;
  rec.dt = dt;
  rec.acceleration.resize(n);
  std::size_t j = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = time.front() + static_cast<double>(k) * dt;
    while (j + 2 < time.size() && time[j + 1] < t) ++j;
    const double w = std::clamp((t - time[j]) / (time[j + 1] - time[j]), 0.0, 1.0);
    rec.acceleration[k] = (1.0 - w) * acceleration[j] + w * acceleration[j + 1];
  }
  rec.final_velocity_before = integrate(rec.acceleration, dt).back();

  // Baseline: least-squares fit c2·t² + c3·t³ of the displacement (keeps the record starting at rest),
  // removed as 2c2 + 6c3·t from the acceleration.
  const std::vector<double> d = integrate(integrate(rec.acceleration, dt), dt);
  Eigen::MatrixXd basis(n, 2);
  Eigen::VectorXd rhs(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * dt;
    basis(k, 0) = t * t;
    basis(k, 1) = t * t * t;
    rhs(k) = d[k];
  }
  const Eigen::Vector2d c = basis.colPivHouseholderQr().solve(rhs);
  for (std::size_t k = 0; k < n; ++k) rec.acceleration[k] -= 2.0 * c(0) + 6.0 * c(1) * static_cast<double>(k) * dt;

  // Scale to the target peak.
  double peak = 0.0;
  for (double a : rec.acceleration) peak = std::max(peak, std::abs(a));
  if (!(peak > 0.0)) throw InputError(field, "all zero", "the accelerogram has no non-zero acceleration");
  for (double& a : rec.acceleration) a *= peak_acceleration / peak;
  rec.velocity = integrate(rec.acceleration, dt);
  rec.displacement = integrate(rec.velocity, dt);
  return rec;
}

Accelerogram loadAccelerogram(const std::string& path, double dt, double peak_acceleration, const std::string& field) {
  std::stringstream in(readDataText(path, "seismic", field));
  std::vector<double> time, acc;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::replace(line.begin(), line.end(), ';', ' ');
    std::istringstream row(line);
    double t, a;
    if (!(row >> t >> a)) {
      if (time.empty()) continue;  // header line
      throw InputError(field, "\"" + line + "\"", "expected two numbers (time [s], acceleration [m/s^2]) per row");
    }
    time.push_back(t);
    acc.push_back(a);
  }
  return correctAccelerogram(time, acc, dt, peak_acceleration, field);
}

}  // namespace maris::seismic
