#include "wec/wec_coupled.hpp"

#include <algorithm>
#include <cmath>

#include "wec/wec_frequency.hpp"
#include "wec/wec_model.hpp"

namespace maris::wec {

CoupledHydro::CoupledHydro(std::vector<Row> rows, Eigen::MatrixXd a_inf, std::string source)
    : rows_(std::move(rows)), a_inf_(std::move(a_inf)), source_(std::move(source)) {
  std::sort(rows_.begin(), rows_.end(), [](const Row& a, const Row& b) { return a.omega < b.omega; });
  dofs_ = static_cast<int>(rows_.front().added_mass.rows());
  std::vector<double> w{0.0};
  for (const auto& r : rows_) w.push_back(r.omega);
  auto series = [&](auto value, double at_zero) {
    std::vector<double> v{at_zero};
    for (const auto& r : rows_) v.push_back(value(r));
    return MonotoneCubic(w, v);
  };
  for (int r = 0; r < dofs_; ++r) {
    for (int c = 0; c < dofs_; ++c) {
      a_.push_back(series([&](const Row& x) { return x.added_mass(r, c); }, rows_.front().added_mass(r, c)));
      b_.push_back(series([&](const Row& x) { return x.damping(r, c); }, 0.0));
    }
    xr_.push_back(series([&](const Row& x) { return x.excitation[r].real(); }, 0.0));
    xi_.push_back(series([&](const Row& x) { return x.excitation[r].imag(); }, 0.0));
  }
}

double CoupledHydro::addedMass(int r, int c, double omega) const {
  return a_[static_cast<std::size_t>(r * dofs_ + c)](omega);
}
double CoupledHydro::damping(int r, int c, double omega) const {
  return b_[static_cast<std::size_t>(r * dofs_ + c)](omega);
}
Complex CoupledHydro::excitation(int r, double omega) const {
  return {xr_[static_cast<std::size_t>(r)](omega), xi_[static_cast<std::size_t>(r)](omega)};
}

std::shared_ptr<const HydroDatabase> CoupledHydro::floatView(int i) const {
  std::vector<TabulatedHydro::Row> rows;
  const int sx = 2 * i, sz = 2 * i + 1;
  for (const auto& r : rows_) {
    TabulatedHydro::Row t;
    t.omega = r.omega;
    t.hydro.surge = {r.added_mass(sx, sx), r.damping(sx, sx), r.excitation[sx]};
    t.hydro.heave = {r.added_mass(sz, sz), r.damping(sz, sz), r.excitation[sz]};
    rows.push_back(t);
  }
  return std::make_shared<TabulatedHydro>(std::move(rows), a_inf_(sx, sx), a_inf_(sz, sz),
                                          source_ + ", body " + std::to_string(i + 1));
}

std::vector<FrequencyResponse> solveCoupledFrequency(const WecModel& model, double omega, int which,
                                                     double pto_override) {
  const CoupledHydro& hydro = *model.coupled;
  const int nf = static_cast<int>(model.floats.size()), nd = 2 * nf;
  Eigen::MatrixXd a(nd, nd), b(nd, nd), t = Eigen::MatrixXd::Zero(nd, nf);
  Eigen::VectorXcd x(nd);
  for (int r = 0; r < nd; ++r) {
    x[r] = hydro.excitation(r, omega);
    for (int c = 0; c < nd; ++c) {
      a(r, c) = hydro.addedMass(r, c, omega);
      b(r, c) = hydro.damping(r, c, omega);
    }
  }
  const double c_w = model.density * model.gravity;
  std::vector<double> b_pto(static_cast<std::size_t>(nf)), k_theta(static_cast<std::size_t>(nf));
  for (int i = 0; i < nf; ++i) {
    const FloatModel& f = model.floats[static_cast<std::size_t>(i)];
    t(2 * i, i) = -f.arm_length * std::sin(f.theta0);
    t(2 * i + 1, i) = f.arm_length * std::cos(f.theta0);
    b_pto[static_cast<std::size_t>(i)] = i == which && pto_override >= 0.0 ? pto_override : f.pto_damping;
    k_theta[static_cast<std::size_t>(i)] = c_w * f.waterplane_area * t(2 * i + 1, i) * t(2 * i + 1, i) + f.pto_stiffness;
  }
  // Pitch impedance matrix and excitation moments.
  const Eigen::MatrixXd j = t.transpose() * a * t, bt = t.transpose() * b * t;
  const Complex iw(0.0, omega);
  Eigen::MatrixXcd z = (-omega * omega * j + iw * bt).cast<Complex>();
  for (int i = 0; i < nf; ++i)
    z(i, i) += -omega * omega * model.floats[static_cast<std::size_t>(i)].inertia_hinge +
               iw * b_pto[static_cast<std::size_t>(i)] + k_theta[static_cast<std::size_t>(i)];
  const Eigen::VectorXcd x_theta = t.transpose().cast<Complex>() * x;
  const Eigen::VectorXcd theta = z.partialPivLu().solve(x_theta);
  // Float motions and the loads on them.
  const Eigen::VectorXcd xi = t.cast<Complex>() * theta;
  const Eigen::MatrixXcd rad = (omega * omega * a).cast<Complex>() - iw * b.cast<Complex>();
  Eigen::VectorXcd q = x + rad * xi;
  std::vector<FrequencyResponse> out(static_cast<std::size_t>(nf));
  const double energy_flux = c_w * model.gravity / (4.0 * omega);  // per a², deep water
  for (int i = 0; i < nf; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const FloatModel& f = model.floats[si];
    q[2 * i + 1] -= c_w * f.waterplane_area * xi[2 * i + 1];
    const double rx = t(2 * i + 1, i), rz = -t(2 * i, i);
    FrequencyResponse& r = out[si];
    r.omega = omega;
    r.pitch = theta[i];
    r.hinge_fx = q[2 * i] + omega * omega * f.mass * xi[2 * i];
    r.hinge_fz = q[2 * i + 1] + omega * omega * f.mass * xi[2 * i + 1];
    r.moment_y = rx * q[2 * i + 1] - rz * q[2 * i] - (iw * b_pto[si] + f.pto_stiffness) * theta[i];
    r.inertia = f.inertia_hinge + j(i, i);
    r.damping = bt(i, i);
    r.stiffness = k_theta[si];
    r.excitation = x_theta[i];
    r.power = 0.5 * b_pto[si] * omega * omega * std::norm(theta[i]);
    r.capture_width = r.power / energy_flux;
    r.capture_width_bound = 3.0 * model.gravity / (omega * omega);
    const double reactance = omega * r.inertia - r.stiffness / omega;
    r.optimal_damping = std::sqrt(r.damping * r.damping + reactance * reactance);
    r.power_bound = r.damping > 0.0 ? std::norm(r.excitation) / (8.0 * r.damping) : 0.0;
  }
  return out;
}

void buildCrossRadiation(WecModel& model, double kernel_duration, double kernel_dt, const RunContext* context) {
  if (!model.coupled) return;
  const CoupledHydro& hydro = *model.coupled;
  const int nd = hydro.dofs();
  const double w_max = hydro.maxFrequency(), d_omega = std::min(0.01, w_max / 400.0);
  // Size of the largest entries, to skip channels that are zero (e.g. surge–heave of one axisymmetric float).
  double b_scale = 0.0, a_scale = 0.0;
  std::vector<double> b_max(static_cast<std::size_t>(nd * nd), 0.0);
  for (const auto& row : hydro.rows())
    for (int r = 0; r < nd; ++r)
      for (int c = 0; c < nd; ++c) {
        auto& m = b_max[static_cast<std::size_t>(r * nd + c)];
        m = std::max(m, std::abs(row.damping(r, c)));
        if (r == c) b_scale = std::max(b_scale, m);
      }
  for (int r = 0; r < nd; ++r) a_scale = std::max(a_scale, std::abs(hydro.addedMassInfinity()(r, r)));
  for (int r = 0; r < nd; ++r)
    for (int c = 0; c < nd; ++c) {
      if (r == c) continue;
      const double a_inf = hydro.addedMassInfinity()(r, c);
      if (b_max[static_cast<std::size_t>(r * nd + c)] <= 1e-6 * b_scale && std::abs(a_inf) <= 1e-6 * a_scale) continue;
      CrossRadiation x;
      x.row = r;
      x.col = c;
      auto damping = [&](double w) { return hydro.damping(r, c, w); };
      auto added = [&](double w) { return hydro.addedMass(r, c, w); };
      x.mode.a_inf = a_inf;
      x.mode.kernel = computeKernel(damping, w_max, d_omega, kernel_duration, kernel_dt, context);
      x.mode.fit = fitModalKernel(x.mode.kernel);
      x.mode.quality = assessFit(x.mode.fit, damping, added, a_inf, 0.3, std::min(3.0, w_max));
      model.cross.push_back(std::move(x));
    }
}

}  // namespace maris::wec
