#include "wec/wec_radiation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <Eigen/SVD>

#include "core/checked_count.hpp"

namespace maris::wec {

double RadiationKernel::at(double t) const {
  if (t < 0.0 || values.empty()) return 0.0;
  const double s = t / dt;
  const auto j = static_cast<std::size_t>(s);
  if (j + 1 >= values.size()) return j + 1 == values.size() && s == static_cast<double>(j) ? values.back() : 0.0;
  const double f = s - static_cast<double>(j);
  return (1.0 - f) * values[j] + f * values[j + 1];
}

RadiationKernel computeKernel(const std::function<double(double)>& damping, double omega_max, double d_omega,
                              double duration, double dt, const RunContext* context) {
  const auto m = static_cast<std::size_t>(
      checkedCount(omega_max / d_omega, kMaxStoredSamples, "parameters.frequency", "radiation-kernel frequencies"));
  const double h = omega_max / static_cast<double>(m);
  std::vector<double> b(m + 1, 0.0);
  for (std::size_t i = 0; i <= m; ++i) b[i] = damping(h * static_cast<double>(i));
  RadiationKernel k;
  k.dt = dt;
  const auto n = static_cast<std::size_t>(checkedCount(std::round(duration / dt), kMaxStoredSamples,
                                                       "parameters.time.time_step", "radiation-kernel samples")) + 1;
  k.values.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    if (context && j % 256 == 0) context->throwIfCancelled();  // 256 samples: ~10 ms at m = 2000
    const double t = dt * static_cast<double>(j);
    double sum = 0.0;
    if (t * h < 1e-6) {
      // Trapezoid (cos ≈ 1 over each segment).
      for (std::size_t i = 0; i < m; ++i) sum += 0.5 * h * (b[i] + b[i + 1]);
    } else {
      // Exact integral of the piecewise-linear B against cos(ωt); sin/cos of ω_i t by rotation.
      const double cd = std::cos(h * t), sd = std::sin(h * t);
      double c0 = 1.0, s0 = 0.0;
      for (std::size_t i = 0; i < m; ++i) {
        const double c1 = c0 * cd - s0 * sd, s1 = s0 * cd + c0 * sd;
        const double slope = (b[i + 1] - b[i]) / h;
        sum += b[i] * (s1 - s0) / t + slope * (h * s1 / t + (c1 - c0) / (t * t));
        c0 = c1;
        s0 = s1;
      }
    }
    k.values[j] = 2.0 / std::numbers::pi * sum;
  }
  return k;
}

double ogilvieAddedMassInfinity(const RadiationKernel& kernel, double omega, double added_mass) {
  double integral = 0.0;
  const double w = omega, dt = kernel.dt;
  for (std::size_t j = 0; j + 1 < kernel.values.size(); ++j) {
    const double t0 = dt * static_cast<double>(j), t1 = t0 + dt;
    const double k0 = kernel.values[j], slope = (kernel.values[j + 1] - k0) / dt;
    // ∫ (k0 + slope (t − t0)) sin(ωt) dt over [t0, t1], exactly.
    integral += k0 * (std::cos(w * t0) - std::cos(w * t1)) / w +
                slope * (-dt * std::cos(w * t1) / w + (std::sin(w * t1) - std::sin(w * t0)) / (w * w));
  }
  return added_mass + integral / omega;
}

OgilvieEstimate ogilvieAddedMassInfinityOverBand(const std::function<double(double)>& damping,
                                                 const std::function<double(double)>& added_mass, double omega_max,
                                                 double omega_lo, double omega_hi, int points) {
  // Kernel long enough for K to decay (60 s) and sampled finely enough to resolve cos(ω_max t).
  const double dt = std::min(0.05, std::numbers::pi / (8.0 * omega_max));
  const RadiationKernel kernel = computeKernel(damping, omega_max, omega_max / 2000.0, 60.0, dt);
  OgilvieEstimate e;
  double lo = 0.0, hi = 0.0;
  for (int i = 0; i < points; ++i) {
    const double w = omega_lo + (omega_hi - omega_lo) * i / std::max(1, points - 1);
    const double a = ogilvieAddedMassInfinity(kernel, w, added_mass(w));
    e.a_inf += a / points;
    lo = i == 0 ? a : std::min(lo, a);
    hi = i == 0 ? a : std::max(hi, a);
  }
  e.spread = hi - lo;
  return e;
}

// ---------------------------------------------------------------------------------------------
double ModalKernel::at(double t) const {
  double k = 0.0;
  for (const auto& m : modes) {
    const std::complex<double> term = m.residue * std::exp(m.pole * t);
    k += m.paired ? 2.0 * term.real() : term.real();
  }
  return k;
}

std::complex<double> ModalKernel::transfer(double omega) const {
  const std::complex<double> iw(0.0, omega);
  std::complex<double> h(0.0, 0.0);
  for (const auto& m : modes) {
    h += m.residue / (iw - m.pole);
    if (m.paired) h += std::conj(m.residue) / (iw - std::conj(m.pole));
  }
  return h;
}

bool ModalKernel::stable() const {
  return std::all_of(modes.begin(), modes.end(), [](const Mode& m) { return m.pole.real() < 0.0; });
}

namespace {

// Hankel matrices of the K samples y_j = K(j·Δ) and the SVD of the first, computed once per fit.
struct Hankel {
  Eigen::MatrixXd h1;
  Eigen::BDCSVD<Eigen::MatrixXd> svd;
  explicit Hankel(const std::vector<double>& y) {
    const int rows = static_cast<int>((y.size() - 1) / 2);
    Eigen::MatrixXd h0(rows, rows);
    h1.resize(rows, rows);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < rows; ++j) {
        h0(i, j) = y[static_cast<std::size_t>(i + j)];
        h1(i, j) = y[static_cast<std::size_t>(i + j + 1)];
      }
    svd.compute(h0, Eigen::ComputeThinU | Eigen::ComputeThinV);
  }
};

// Poles of the order-n ERA realization A = Σ^{-1/2} Uᵀ H1 V Σ^{-1/2}, mapped to continuous time.
std::vector<std::complex<double>> eraPoles(const Hankel& hankel, double delta, int order) {
  const int n = std::min<int>(order, static_cast<int>(hankel.h1.rows()));
  const Eigen::VectorXd s = hankel.svd.singularValues().head(n);
  const Eigen::VectorXd s_inv_sqrt = s.cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd a = s_inv_sqrt.asDiagonal() * hankel.svd.matrixU().leftCols(n).transpose() * hankel.h1 *
                            hankel.svd.matrixV().leftCols(n) * s_inv_sqrt.asDiagonal();
  Eigen::EigenSolver<Eigen::MatrixXd> eig(a, false);
  std::vector<std::complex<double>> poles;
  for (int i = 0; i < n; ++i) {
    const std::complex<double> z = eig.eigenvalues()(i);
    if (std::abs(z) < 1e-12) continue;
    // A negative real eigenvalue has no real continuous counterpart (Nyquist mode): skip it.
    if (std::abs(z.imag()) < 1e-12 && z.real() < 0.0) continue;
    std::complex<double> p = std::log(z) / delta;
    if (p.real() >= 0.0) p = {-std::max(std::abs(p.real()), 1e-3), p.imag()};  // reflect unstable poles
    if (p.imag() < -1e-12) continue;  // keep one of each conjugate pair
    poles.push_back(std::abs(p.imag()) < 1e-12 ? std::complex<double>(p.real(), 0.0) : p);
  }
  return poles;
}

// Least-squares residues for fixed poles; returns the fit with its R².
ModalKernel residuesFor(const std::vector<std::complex<double>>& poles, const std::vector<double>& y, double delta) {
  ModalKernel fit;
  int cols = 0;
  for (const auto& p : poles) cols += p.imag() == 0.0 ? 1 : 2;
  const auto rows = static_cast<Eigen::Index>(y.size());
  Eigen::MatrixXd basis(rows, cols);
  Eigen::VectorXd target(rows);
  for (Eigen::Index j = 0; j < rows; ++j) {
    const double t = delta * static_cast<double>(j);
    target(j) = y[static_cast<std::size_t>(j)];
    int c = 0;
    for (const auto& p : poles) {
      const std::complex<double> e = std::exp(p * t);
      if (p.imag() == 0.0) {
        basis(j, c++) = e.real();
      } else {  // 2 Re((α + iβ) e) = 2α Re e − 2β Im e
        basis(j, c++) = 2.0 * e.real();
        basis(j, c++) = -2.0 * e.imag();
      }
    }
  }
  const Eigen::VectorXd coef = basis.colPivHouseholderQr().solve(target);
  int c = 0;
  for (const auto& p : poles) {
    ModalKernel::Mode m;
    m.pole = p;
    m.paired = p.imag() != 0.0;
    m.residue = m.paired ? std::complex<double>(coef(c), coef(c + 1)) : std::complex<double>(coef(c), 0.0);
    c += m.paired ? 2 : 1;
    fit.modes.push_back(m);
  }
  fit.order = cols;
  const Eigen::VectorXd residual = basis * coef - target;
  const double mean = target.mean();
  const double total = (target.array() - mean).square().sum();
  fit.r_squared = total > 0.0 ? 1.0 - residual.squaredNorm() / total : 1.0;
  return fit;
}

}  // namespace

ModalKernel fitModalKernel(const RadiationKernel& kernel, const KernelFitOptions& options) {
  // Resample the kernel to `samples` + 1 points over its duration.
  const double delta = kernel.duration() / options.samples;
  std::vector<double> y(static_cast<std::size_t>(options.samples) + 1);
  for (std::size_t j = 0; j < y.size(); ++j) y[j] = kernel.at(delta * static_cast<double>(j));
  const Hankel hankel(y);
  ModalKernel best;
  best.r_squared = -1e300;
  for (int order = 2; order <= options.max_order; order += 2) {
    const auto poles = eraPoles(hankel, delta, order);
    if (poles.empty()) continue;
    ModalKernel fit = residuesFor(poles, y, delta);
    if (fit.r_squared > best.r_squared) best = fit;
    if (best.r_squared >= options.r_squared_target) break;
  }
  return best;
}

FitQuality assessFit(const ModalKernel& fit, const std::function<double(double)>& damping,
                     const std::function<double(double)>& added_mass, double a_inf, double omega_lo,
                     double omega_hi, int points) {
  FitQuality q;
  double b_max = 0.0, e_b = 0.0, e_a = 0.0, min_re = 1e300;
  for (int i = 0; i < points; ++i) {
    const double w = omega_lo + (omega_hi - omega_lo) * i / (points - 1);
    const std::complex<double> h = fit.transfer(w);
    const double b = damping(w);
    b_max = std::max(b_max, b);
    e_b = std::max(e_b, std::abs(h.real() - b));
    e_a = std::max(e_a, std::abs(h.imag() - w * (added_mass(w) - a_inf)));
    min_re = std::min(min_re, h.real());
  }
  q.damping_error = e_b / b_max;
  q.added_mass_error = e_a / b_max;
  q.min_real_part = min_re / b_max;
  return q;
}

// ---------------------------------------------------------------------------------------------
DirectConvolution::DirectConvolution(const RadiationKernel& kernel_at_step)
    : kernel_(kernel_at_step.values), dt_(kernel_at_step.dt) {
  const std::size_t n = kernel_.size();
  const std::size_t taper = std::max<std::size_t>(1, n / 10);
  for (std::size_t j = n - taper; j < n; ++j) {
    const double f = static_cast<double>(j - (n - taper) + 1) / static_cast<double>(taper);
    kernel_[j] *= 0.5 * (1.0 + std::cos(std::numbers::pi * f));
  }
  history_.assign(n, 0.0);
}

void DirectConvolution::push(double velocity) {
  head_ = (head_ + 1) % history_.size();
  history_[head_] = velocity;
  ++count_;
}

double DirectConvolution::valueNow() const {
  if (count_ < 2) return 0.0;
  const std::size_t n = history_.size();
  const std::size_t last = std::min(count_ - 1, n - 1);  // lag of the oldest sample used
  double sum = 0.5 * kernel_[0] * history_[head_];
  for (std::size_t lag = 1; lag < last; ++lag) sum += kernel_[lag] * history_[(head_ + n - lag) % n];
  sum += 0.5 * kernel_[last] * history_[(head_ + n - last) % n];
  return dt_ * sum;
}

}  // namespace maris::wec
