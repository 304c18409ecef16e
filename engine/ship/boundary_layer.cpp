#include "ship/boundary_layer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace maris::ship {

namespace {

// Thwaites' shape factor H(λ), Cebeci & Bradshaw (1977) fit, λ limited to the fit's range.
double thwaitesShapeFactor(double lambda) {
  const double l = std::clamp(lambda, -0.09, 0.1);
  return l >= 0 ? 2.61 - 3.75 * l + 5.24 * l * l : 2.088 + 0.0731 / (l + 0.14);
}

// Head's entrainment shape factor H1(H) and its inverse (Cebeci & Bradshaw 1977, eqs 8.3.x).
double headH1(double H) {
  return H <= 1.6 ? 3.3 + 0.8234 * std::pow(H - 1.1, -1.287) : 3.3 + 1.5501 * std::pow(H - 0.6778, -3.064);
}
double headH(double H1) {
  const double d = std::max(H1 - 3.3, 1e-6);
  return H1 >= 5.3 ? 1.1 + 0.86 * std::pow(d, -0.777) : 0.6778 + 1.1536 * std::pow(d, -0.326);
}

constexpr double kSeparationShapeFactor = 2.4;  // turbulent separation (Head's method, usual criterion)
constexpr double kMaxWakeSlope = 0.1;           // [-] dδ*/ds limit after separation (≈ 6°)

}  // namespace

std::vector<double> thinBodyEdgeVelocity(const std::vector<double>& s, const std::vector<double>& y) {
  const std::size_t n = s.size();
  std::vector<double> slope(n - 1), mid(n - 1), u_mid(n - 1, 1.0), u(n, 1.0);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    slope[k] = (y[k + 1] - y[k]) / (s[k + 1] - s[k]);
    mid[k] = 0.5 * (s[k] + s[k + 1]);
  }
  // Source panels of constant slope: ∫ c dσ/(s − σ) over a panel = c ln|(s − s_l)/(s − s_{l+1})|; a panel's
  // own contribution at its midpoint vanishes (principal value).
  for (std::size_t k = 0; k + 1 < n; ++k) {
    double sum = 0;
    for (std::size_t l = 0; l + 1 < n; ++l) {
      if (l == k || slope[l] == 0.0) continue;
      sum += slope[l] * std::log(std::abs((mid[k] - s[l]) / (mid[k] - s[l + 1])));
    }
    u_mid[k] = 1.0 + sum / std::numbers::pi;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double v = i == 0 ? u_mid.front() : (i == n - 1 ? u_mid.back() : 0.5 * (u_mid[i - 1] + u_mid[i]));
    u[i] = std::clamp(v, 0.5, 1.5);
  }
  return u;
}

BoundaryLayerProfile solveBoundaryLayer(const std::vector<double>& s, const std::vector<double>& ue_ratio, double U,
                                        double nu, double s_trip) {
  const std::size_t n = s.size();
  BoundaryLayerProfile p;
  p.momentum_thickness.assign(n, 0.0);
  p.shape_factor.assign(n, 2.61);
  p.displacement_thickness.assign(n, 0.0);
  std::vector<double> ue(n);
  for (std::size_t i = 0; i < n; ++i) ue[i] = U * ue_ratio[i];
  auto dueds = [&](std::size_t i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 < n ? i + 1 : n - 1;
    return (ue[b] - ue[a]) / (s[b] - s[a]);
  };

  // Laminar (Thwaites) until the trip, Michel's criterion or laminar separation.
  double integral = 0;  // ∫ u_e⁵ ds
  std::size_t i = 1;
  for (; i < n; ++i) {
    integral += 0.5 * (std::pow(ue[i - 1], 5) + std::pow(ue[i], 5)) * (s[i] - s[i - 1]);
    const double theta2 = 0.45 * nu * integral / std::pow(ue[i], 6);
    const double lambda = theta2 * dueds(i) / nu;
    p.momentum_thickness[i] = std::sqrt(theta2);
    p.shape_factor[i] = thwaitesShapeFactor(lambda);
    const double re_s = ue[i] * s[i] / nu, re_theta = ue[i] * p.momentum_thickness[i] / nu;
    const bool michel = re_theta > 1.174 * (1.0 + 22400.0 / re_s) * std::pow(re_s, 0.46);
    if (s[i] >= s_trip || michel || lambda < -0.09) break;
  }
  // Turbulent (Head), Heun steps, 4 per interval; state θ and E = u_e θ H1.
  if (i < n) {
    p.transition_index = static_cast<int>(i);
    double theta = p.momentum_thickness[i], H = 1.4;
    double E = ue[i] * theta * headH1(H);
    p.shape_factor[i] = H;
    for (std::size_t k = i; k + 1 < n && p.separation_index < 0; ++k) {
      const double ds = (s[k + 1] - s[k]) / 4.0, grad = (ue[k + 1] - ue[k]) / (s[k + 1] - s[k]);
      for (int sub = 0; sub < 4; ++sub) {
        const double s0 = s[k] + sub * ds;
        auto rhs = [&](double sv, double th, double e, double& dth, double& de) {
          const double u = ue[k] + grad * (sv - s[k]);
          const double h = headH(e / (u * th));
          const double cf = 0.246 * std::pow(10.0, -0.678 * h) * std::pow(std::max(u * th / nu, 10.0), -0.268);
          dth = 0.5 * cf - (h + 2.0) * th / u * grad;
          de = u * 0.0306 * std::pow(std::max(e / (u * th) - 3.0, 1e-6), -0.6169);
        };
        double a1, b1, a2, b2;
        rhs(s0, theta, E, a1, b1);
        const double th_p = std::max(theta + ds * a1, 1e-12), e_p = E + ds * b1;
        rhs(s0 + ds, th_p, e_p, a2, b2);
        theta = std::max(theta + 0.5 * ds * (a1 + a2), 1e-12);
        E += 0.5 * ds * (b1 + b2);
      }
      H = headH(E / (ue[k + 1] * theta));
      p.momentum_thickness[k + 1] = theta;
      p.shape_factor[k + 1] = H;
      if (H >= kSeparationShapeFactor) p.separation_index = static_cast<int>(k + 1);
    }
  }
  for (std::size_t k = 0; k < n; ++k) p.displacement_thickness[k] = p.shape_factor[k] * p.momentum_thickness[k];
  // Separated: δ* continues along the separating streamline's direction (slope at separation, limited).
  // The separation point is interpolated to H = 2.4 inside its interval, so that δ* downstream varies
  // continuously with speed instead of jumping when separation passes a node.
  if (p.separation_index > 0) {
    const std::size_t k0 = static_cast<std::size_t>(p.separation_index);
    const double h0 = p.shape_factor[k0 - 1], h1 = p.shape_factor[k0];
    const double t = h1 > h0 ? std::clamp((kSeparationShapeFactor - h0) / (h1 - h0), 0.0, 1.0) : 1.0;
    const double d0 = p.displacement_thickness[k0 - 1], d1 = p.displacement_thickness[k0];
    const double s_sep = s[k0 - 1] + t * (s[k0] - s[k0 - 1]), d_sep = d0 + t * (d1 - d0);
    const double slope = std::clamp((d1 - d0) / (s[k0] - s[k0 - 1]), 0.0, kMaxWakeSlope);
    for (std::size_t k = k0; k < n; ++k) {
      p.displacement_thickness[k] = d_sep + slope * (s[k] - s_sep);
      p.shape_factor[k] = kSeparationShapeFactor;
      p.momentum_thickness[k] = p.displacement_thickness[k] / kSeparationShapeFactor;
    }
  }
  return p;
}

TangencyCorrection::TangencyCorrection(HullGrid grid, double trip_fraction)
    : grid_(std::move(grid)), trip_fraction_(trip_fraction) {
  const int nx = grid_.nx();
  waterlines_.resize(grid_.nz());
  for (int j = 0; j < grid_.nz(); ++j) {
    Waterline& w = waterlines_[j];
    for (int i = 0; i < nx; ++i)
      if (grid_.half_breadth(i, j) > 0) {
        if (w.stern < 0) w.stern = i;
        w.bow = i;
      }
    if (w.bow < 0) continue;
    // March nodes from the leading edge (the zero station ahead of the bow, if any) to the trailing edge.
    const int lead = std::min(w.bow + 1, nx - 1), trail = std::max(w.stern - 1, 0);
    double arc = 0;
    for (int i = lead; i >= trail; --i) {
      if (i < lead) arc += std::hypot(grid_.dx, grid_.half_breadth(i, j) - grid_.half_breadth(i + 1, j));
      w.s.push_back(arc);
      w.y.push_back(grid_.half_breadth(i, j));
    }
    if (w.s.size() < 3) {
      w.bow = w.stern = -1;
      continue;
    }
    w.ue = thinBodyEdgeVelocity(w.s, w.y);
    w.bow = lead;
    w.stern = trail;
  }
}

std::vector<double> TangencyCorrection::displacementThickness(int j, double speed, double viscosity) const {
  std::vector<double> out(grid_.nx(), 0.0);
  const Waterline& w = waterlines_[j];
  if (w.bow < 0) return out;
  const auto bl = solveBoundaryLayer(w.s, w.ue, speed, viscosity, trip_fraction_ * w.s.back());
  for (std::size_t k = 0; k < w.s.size(); ++k) out[w.bow - static_cast<int>(k)] = bl.displacement_thickness[k];
  return out;
}

HullGrid TangencyCorrection::correctedGrid(double speed, double viscosity, int* clamped) const {
  HullGrid out = grid_;
  const double dx = grid_.dx, max_angle = 80.0 * std::numbers::pi / 180.0;
  int count = 0;
  for (int j = 0; j < grid_.nz(); ++j) {
    const Waterline& w = waterlines_[j];
    if (w.bow < 0) continue;
    const std::vector<double> dstar = displacementThickness(j, speed, viscosity);
    // Integrate the rotated slope aft from the leading edge (x decreasing): Y_eff(x − dx) = Y_eff(x) − dx·Y_x,BL.
    double y_eff = grid_.half_breadth(w.bow, j);
    for (int i = w.bow - 1; i >= 0; --i) {
      if (i >= w.stern) {
        const double slope = (grid_.half_breadth(i + 1, j) - grid_.half_breadth(i, j)) / dx;
        const double dslope = (dstar[i + 1] - dstar[i]) / dx;
        double angle = std::atan(slope) + std::atan(dslope);
        if (std::abs(angle) > max_angle) {
          angle = std::copysign(max_angle, angle);
          ++count;
        }
        y_eff = std::max(0.0, y_eff - dx * std::tan(angle));
      }
      // Aft of the trailing edge the displacement surface carries on without sources (constant Y_eff).
      out.half_breadth(i, j) = y_eff;
    }
  }
  if (clamped) *clamped = count;
  return out;
}

void TangencyKochin::prepare(double speed) {
  kochin_ = std::make_unique<GridKochin>(correction_->correctedGrid(speed, viscosity_, &clamped_));
}

void TangencyKochin::evaluate(double k0, double lambda, double& fine, double& coarse) {
  kochin_->evaluate(k0, lambda, fine, coarse);
}

}  // namespace maris::ship
