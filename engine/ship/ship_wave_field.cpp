#include "ship/ship_wave_field.hpp"

#include "ship/kelvin_source.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace maris::ship {

namespace {

using Complex = std::complex<double>;

// The hull's source sheet: ∂Y/∂x per station panel (Y bilinear, so the slope is exact and linear in z on each
// panel) and the line sources of open ends, reduced for one wave number k to what the x integral needs.
class SourceSheet {
 public:
  explicit SourceSheet(const HullGrid& grid) : grid_(grid) {
    const int nx = grid.nx();
    slope_ = (grid.half_breadth.bottomRows(nx - 1) - grid.half_breadth.topRows(nx - 1)) / grid.dx;
    depth_weights_.resize(grid.nz());
    panel_depth_.resize(nx - 1);
    suffix_.resize(nx);
  }

  double xAft() const { return grid_.x_aft; }
  double xFore() const { return grid_.x(grid_.nx() - 1); }

  // Prepares F(x; θ) for k = k0 λ², κ = k0 λ: the depth integrals ∫ ∂Y/∂x e^{kz} dz (exact for Y linear in z
  // between waterlines) and the suffix sums over the panels ahead.
  void prepare(double k, double kappa) {
    kappa_ = kappa;
    const double h = grid_.dz;
    depth_weights_.setZero();
    for (int j = 0; j + 1 < grid_.nz(); ++j) {
      const double upper = grid_.z(j), lower = grid_.z(j + 1);
      double w_upper, w_lower;  // ∫ over [lower, upper] of the hat functions of the two nodes, times e^{kz}
      if (k * h < 1e-5) {
        w_upper = w_lower = 0.5 * h * std::exp(k * 0.5 * (upper + lower));
      } else {
        const double e_up = std::exp(k * upper), e_lo = std::exp(k * lower);
        const double whole = (e_up - e_lo) / k;          // ∫ e^{kz} dz
        w_upper = e_up / k - whole / (k * h);            // ∫ (z − lower)/h e^{kz} dz
        w_lower = whole - w_upper;
      }
      depth_weights_[j] += w_upper;
      depth_weights_[j + 1] += w_lower;
    }
    panel_depth_ = slope_ * depth_weights_;
    const int panels = static_cast<int>(panel_depth_.size());
    suffix_[panels] = 0.0;
    for (int p = panels - 1; p >= 0; --p)
      suffix_[p] = suffix_[p + 1] + panel_depth_[p] * stripIntegral(grid_.x(p), grid_.x(p + 1));
    aft_end_ = grid_.half_breadth.row(0).dot(depth_weights_) * std::polar(1.0, kappa * xAft());
    fore_end_ = -grid_.half_breadth.row(grid_.nx() - 1).dot(depth_weights_) * std::polar(1.0, kappa * xFore());
    // F(x) = constant_p + slope_p e^{iκx} on panel p (see split).
    constant_.resize(panels);
    for (int p = 0; p < panels; ++p)
      constant_[p] = panel_depth_[p] * std::polar(1.0, kappa * grid_.x(p + 1)) / Complex(0.0, kappa) + suffix_[p + 1] + fore_end_;
  }

  // F(x) = a + b e^{iκx}: (a, b) for the x given, so that F at many points of one panel costs no exponential.
  void split(double x, Complex& a, Complex& b) const {
    if (x >= xFore()) {
      a = b = 0.0;
      return;
    }
    if (x < xAft()) {
      a = suffix_[0] + aft_end_ + fore_end_;
      b = 0.0;
      return;
    }
    const int panels = static_cast<int>(panel_depth_.size());
    const int p = std::min(static_cast<int>((x - xAft()) / grid_.dx), panels - 1);
    a = constant_[p];
    b = Complex(0.0, panel_depth_[p] / kappa_);  // −P/(iκ)
  }

  // F(x; θ) [m²]: the Kochin function of the sources ahead of x (ξ > x).
  Complex aheadOf(double x) const {
    if (x >= xFore()) return 0.0;
    if (x < xAft()) return suffix_[0] + aft_end_ + fore_end_;
    const int panels = static_cast<int>(panel_depth_.size());
    const int p = std::min(static_cast<int>((x - xAft()) / grid_.dx), panels - 1);
    return panel_depth_[p] * stripIntegral(x, grid_.x(p + 1)) + suffix_[p + 1] + fore_end_;
  }

 private:
  Complex stripIntegral(double a, double b) const {  // ∫_a^b e^{iκξ} dξ
    return (std::polar(1.0, kappa_ * b) - std::polar(1.0, kappa_ * a)) / Complex(0.0, kappa_);
  }

  const HullGrid& grid_;
  Eigen::MatrixXd slope_;  // (nx − 1) × nz: ∂Y/∂x on each panel at each waterline
  Eigen::VectorXd depth_weights_, panel_depth_;
  std::vector<Complex> suffix_, constant_;
  double kappa_ = 0;
  Complex aft_end_, fore_end_;
};

// Half-breadth at the waterline (z = 0) at x, linear between stations; 0 outside the hull.
double waterlineHalfBreadth(const HullGrid& grid, double x) {
  const double s = (x - grid.x_aft) / grid.dx;
  if (s < 0 || s > grid.nx() - 1) return 0.0;
  const int i = std::min(static_cast<int>(s), grid.nx() - 2);
  const double t = s - i;
  return (1 - t) * grid.half_breadth(i, 0) + t * grid.half_breadth(i + 1, 0);
}

}  // namespace

ShipWaveField thinShipWaveField(const HullGrid& grid, double speed, double gravity, const WaveFieldRegion& region,
                                bool with_local, const std::function<bool()>& cancelled) {
  const double k0 = gravity / (speed * speed);
  SourceSheet sheet(grid);
  const double below_stern = sheet.xAft() - 1.0;

  // λ range: up to where the whole hull's spectrum |F|² λ³ falls below 1e-6 of its largest value (as the far
  // field does).
  double peak = 0, lambda_max = 1.0;
  for (double lambda = 1.0; lambda < 200.0; lambda *= 1.02) {
    sheet.prepare(k0 * lambda * lambda, k0 * lambda);
    const double density = std::norm(sheet.aheadOf(below_stern)) * lambda * lambda * lambda;
    peak = std::max(peak, density);
    if (density > 1e-6 * peak) lambda_max = lambda;
  }
  // Nodes in u (λ = cosh u): 6 per radian of the phase k0 (|x − ξ| λ + |y| λ² sin θ) at the farthest pair.
  const double u_max = std::acosh(lambda_max);
  const double r_far = std::max(sheet.xFore() - region.x_from, 0.0) + region.half_width;
  const int nu = std::clamp(static_cast<int>(6.0 * k0 * r_far * lambda_max * lambda_max * u_max), 200, 20000);
  const double du = u_max / nu;

  ShipWaveField out;
  out.lambda_max = lambda_max;
  WavePattern& w = out.pattern;
  w.x.resize(region.nx);
  w.y.resize(region.ny);
  for (int i = 0; i < region.nx; ++i) w.x[i] = region.x_from + (region.x_to - region.x_from) * i / (region.nx - 1);
  for (int j = 0; j < region.ny; ++j) w.y[j] = -region.half_width + 2.0 * region.half_width * j / (region.ny - 1);

  // ζ_ij = Σ_k Re(A_k(x_i) e^{−iκ_k x_i}) · 2 cos(k_y,k y_j): ±θ pair up (the hull is symmetric), one GEMM.
  // The amplitude A = −(2/π) k0 sec³θ F: the wave term of the Kelvin source (kelvin_source.hpp) summed over the
  // sheet of density q = −2U ∂Y/∂ξ.
  // With the local part, the total also needs the wave term where Havelock's form has it, H(−ϖ) (the sources
  // ahead of x + y tan θ), and not H(−x'): the difference D is added per point and θ wherever that cut and x
  // fall on different sides of a source, i.e. where the Kochin function ahead of them differs.
  Eigen::MatrixXd along(region.nx, nu + 1), across(nu + 1, region.ny);
  Eigen::MatrixXd havelock = Eigen::MatrixXd::Zero(region.nx, region.ny);
  std::vector<Complex> ahead(region.nx), phase_x(region.nx);
  for (int k = 0; k <= nu; ++k) {
    if (k % 64 == 0 && cancelled && cancelled()) break;
    const double u = k * du, lambda = std::cosh(u);
    const double kappa = k0 * lambda, wave_number = k0 * lambda * lambda;
    sheet.prepare(wave_number, kappa);
    const double end = (k == 0 || k == nu) ? 0.5 : 1.0;
    const Complex weight = (-2.0 / std::numbers::pi) * k0 * lambda * lambda * lambda * (end * du / lambda);
    for (int i = 0; i < region.nx; ++i) {
      ahead[i] = sheet.aheadOf(w.x[i]);
      phase_x[i] = std::polar(1.0, -kappa * w.x[i]);
      along(i, k) = (weight * ahead[i] * phase_x[i]).real();
    }
    const double ky = wave_number * std::tanh(u);  // k sin θ (sin θ = tanh u)
    for (int j = 0; j < region.ny; ++j) across(k, j) = 2.0 * std::cos(ky * w.y[j]);
    if (!with_local) continue;
    // D per point: Re[weight (F(cut) − F(x)) e^{−iκx} e^{∓i k_y y}] with cut = x ± y tan θ; κ tan θ = k_y, so
    // with F(cut) = a + b e^{iκ cut} this is Re[weight ((a − F(x)) e^{−iκx} e^{∓i k_y y} + b)].
    const double tan_theta = std::sinh(u);
    for (int j = 0; j < region.ny; ++j) {
      if (w.y[j] <= 0) continue;  // y = 0: no difference; y < 0: mirrored below
      const Complex ey = std::polar(1.0, -ky * w.y[j]);
      for (int i = 0; i < region.nx; ++i) {
        const bool before = w.x[i] < sheet.xAft(), beyond = w.x[i] >= sheet.xFore();
        const Complex& ex = phase_x[i];
        for (int sign = -1; sign <= 1; sign += 2) {
          const double cut = w.x[i] + sign * tan_theta * w.y[j];
          if ((before && cut < sheet.xAft()) || (beyond && cut >= sheet.xFore())) continue;
          Complex a, b;
          sheet.split(cut, a, b);
          havelock(i, j) += (weight * ((a - ahead[i]) * ex * (sign > 0 ? ey : std::conj(ey)) + b)).real();
        }
      }
    }
  }
  w.elevation = along * across;
  out.wave = w.elevation;
  if (with_local) {
    for (int j = 0; j < region.ny; ++j)
      if (w.y[j] < 0) havelock.col(j) = havelock.col(region.ny - 1 - j);  // the grid is symmetric in y
    out.local = havelock + thinShipLocalElevation(grid, k0, w.x, w.y, 49, 9, 2, 3, cancelled);
    w.elevation += out.local;
  }

  // Inside the waterline: the elevation at the hull's side (the nearest point outside on the same side). The
  // tolerance keeps the choice symmetric where ±y_j differ by rounding.
  for (int i = 0; i < region.nx; ++i) {
    const double half = waterlineHalfBreadth(grid, w.x[i]) * (1.0 - 1e-9);
    if (half <= 0) continue;
    int first_out = region.ny;  // first j with y_j ≥ half (starboard side, y > 0)
    for (int j = 0; j < region.ny; ++j)
      if (w.y[j] >= half) {
        first_out = j;
        break;
      }
    int last_out = -1;  // last j with y_j ≤ −half
    for (int j = region.ny - 1; j >= 0; --j)
      if (w.y[j] <= -half) {
        last_out = j;
        break;
      }
    for (int j = last_out + 1; j < first_out; ++j) {
      const bool port = w.y[j] < 0 && last_out >= 0;
      const int source = port ? last_out : (first_out < region.ny ? first_out : last_out);
      if (source < 0 || source >= region.ny) continue;
      w.elevation(i, j) = w.elevation(i, source);
      out.wave(i, j) = out.wave(i, source);
      if (with_local) out.local(i, j) = out.local(i, source);
    }
  }
  return out;
}

}  // namespace maris::ship
