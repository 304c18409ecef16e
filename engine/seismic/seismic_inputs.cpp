#include "seismic/seismic_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "core/checked_count.hpp"
#include "core/errors.hpp"
#include "core/formats/format_detect.hpp"
#include "core/formats/peer_at2.hpp"
#include "core/resources.hpp"
#include "core/table_reader.hpp"

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
  const std::string text = readDataText(path, "seismic", field);
  std::vector<double> time, acc;
  if (formats::detectFormat(text) == formats::FileFormat::peer_at2) {
    // A PEER record: uniform step, accelerations in g (converted to m/s² by the reader).
    const formats::PeerRecord rec = formats::parsePeerAt2(text, field, path);
    acc = rec.acceleration;
    for (std::size_t k = 0; k < acc.size(); ++k) time.push_back(static_cast<double>(k) * rec.dt);
  } else {
    TableSpec spec{field, path, "two columns: time [s], acceleration [m/s^2]; or a PEER .AT2 record"};
    spec.names = TableSpec::Names::optional;
    spec.min_columns = 2;
    refuseForeignFormat(text, spec);
    const TextTable table = parseTable(text, spec);
    for (const auto& row : table.rows) {
      time.push_back(*row.cells[0]);
      acc.push_back(*row.cells[1]);
    }
  }
  return correctAccelerogram(time, acc, dt, peak_acceleration, field);
}

}  // namespace maris::seismic
