#include "ship/michell_resistance.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <queue>

#include "ship/michell_quadrature.hpp"

namespace maris::ship {

namespace {

// Gauss–Kronrod 7/15 nodes and weights on [-1, 1] (QUADPACK qk15): Kronrod nodes ±xk[i]; the Gauss nodes are
// the odd-indexed ones.
constexpr double kXk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                           0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                           0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                           0.207784955007898467600689403773245, 0.0};
constexpr double kWk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                           0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                           0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                           0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

// One panel u ∈ [u0, u1] of ∫ |F(cosh u)|² cosh²u du (= ∫ |F|² λ²/√(λ²−1) dλ).
struct Panel {
  double u0 = 0, u1 = 0;
  double fine = 0, coarse = 0, error = 0;
  double lambda0() const { return std::cosh(u0); }
  double lambda1() const { return std::cosh(u1); }
};

class PanelIntegrator {
 public:
  PanelIntegrator(KochinFunction& kochin, double k0, const RunContext* context)
      : kochin_(kochin), k0_(k0), context_(context) {}

  void evaluate(Panel& p) {
    const double mid = 0.5 * (p.u0 + p.u1), half = 0.5 * (p.u1 - p.u0);
    double kf = 0, kc = 0, gf = 0;
    auto node = [&](double u, double weight_k, double weight_g) {
      const double lambda = std::cosh(u);
      double f = 0, c = 0;
      kochin_.evaluate(k0_, lambda, f, c);
      const double jac = lambda * lambda;  // |F|² λ²/√(λ²−1) dλ = |F|² cosh²u du
      kf += weight_k * f * jac;
      kc += weight_k * c * jac;
      gf += weight_g * f * jac;
    };
    node(mid, kWk[7], kWg[3]);
    for (int k = 0; k < 7; ++k) {
      const double wg = (k % 2 == 1) ? kWg[k / 2] : 0.0;
      node(mid - half * kXk[k], kWk[k], wg);
      node(mid + half * kXk[k], kWk[k], wg);
    }
    p.fine = kf * half;
    p.coarse = kc * half;
    p.error = std::abs(kf - gf) * half;
    evaluations += 15;
    if (context_ && evaluations % 150 == 0) context_->throwIfCancelled();
  }

  long evaluations = 0;

 private:
  KochinFunction& kochin_;
  double k0_;
  const RunContext* context_;
};

// Panels covering λ ∈ [lambda_from, lambda_to], each at most one interference period (and at most half its
// start λ + 0.5, so that panels grow geometrically when the period is long).
void appendPanels(std::vector<Panel>& panels, double lambda_from, double lambda_to, double period) {
  double l0 = lambda_from;
  while (l0 < lambda_to * (1 - 1e-14)) {
    const double l1 = std::min(lambda_to, l0 + std::min(period, 0.5 * l0 + 0.5));
    panels.push_back({std::acosh(l0), std::acosh(l1), 0, 0, 0});
    l0 = l1;
  }
}

// Mean of g(λ) over the panels whose centre lies in [lo, hi), and the covered λ range.
struct OctaveMean {
  double mean = 0, lambda = 0;
};
OctaveMean octaveMean(const std::vector<Panel>& panels, double lo, double hi) {
  double sum = 0, width = 0, a = hi, b = lo;
  for (const auto& p : panels) {
    const double l0 = p.lambda0(), l1 = p.lambda1(), c = 0.5 * (l0 + l1);
    if (c < lo || c >= hi) continue;
    sum += p.fine;
    width += l1 - l0;
    a = std::min(a, l0);
    b = std::max(b, l1);
  }
  if (width <= 0) return {};
  return {sum / width, std::sqrt(a * b)};
}

}  // namespace

GridKochin::GridKochin(HullGrid grid, bool with_coarse) : fine_(std::move(grid)), with_coarse_(with_coarse) {
  weights_.resize(fine_.nz());
  sections_.resize(fine_.nx());
  if (with_coarse_) {
    coarse_ = fine_.coarsened();
    weights_coarse_.resize(coarse_.nz());
    sections_coarse_.resize(coarse_.nx());
  }
}

std::complex<double> GridKochin::kochin(const HullGrid& g, double k0, double lambda, Eigen::VectorXd& w,
                                        Eigen::VectorXd& Z) {
  const double kappa = k0 * lambda, b = kappa * lambda;
  // Depth integral of every station: Z_i = ∫ Y(x_i, z) e^{bz} dz (exact for piecewise linear Y).
  int last = 0;
  expTrapezoidWeights(b, g.dz, w, &last);
  Z.noalias() = g.half_breadth.leftCols(last + 1) * w.head(last + 1);
  // ∫ Y_x e^{iκx} = [Z e^{iκx}]_ends − iκ ∫ Z e^{iκx} dx, x measured from mid-length (|F| is shift invariant).
  const int n = g.nx() - 1;
  const double half = 0.5 * n * g.dx;
  const std::complex<double> I = filonIntegral(Z, -half, g.dx, kappa);
  const std::complex<double> e_fwd = std::polar(1.0, kappa * half), e_aft = std::conj(e_fwd);
  return Z[n] * e_fwd - Z[0] * e_aft - std::complex<double>(0.0, kappa) * I;
}

std::complex<double> GridKochin::amplitude(double k0, double lambda) {
  return kochin(fine_, k0, lambda, weights_, sections_);
}

void GridKochin::evaluate(double k0, double lambda, double& fine, double& coarse) {
  fine = std::norm(kochin(fine_, k0, lambda, weights_, sections_));
  coarse = with_coarse_ ? std::norm(kochin(coarse_, k0, lambda, weights_coarse_, sections_coarse_)) : fine;
}

void WigleyKochin::evaluate(double k0, double lambda, double& fine, double& coarse) {
  fine = coarse = wigleyKochinSquared(length_, beam_, draft_, k0, lambda);
}

WaveResistance michellWaveResistance(KochinFunction& kochin, double speed, double gravity, double density,
                                     const MichellSettings& s, const RunContext* context) {
  kochin.prepare(speed);
  const double k0 = gravity / (speed * speed);
  const double k0_hat = k0 * s.wave_number_factor;
  const double k_pre = s.prefactor_uses_corrected_wave_number ? k0_hat : k0;
  const double prefactor = 4.0 / std::numbers::pi * density * speed * speed * k_pre * k_pre;
  const double period = 2.0 * std::numbers::pi / (k0_hat * kochin.length());
  PanelIntegrator integrator(kochin, k0_hat, context);
  WaveResistance r;

  // The paper's short-wave discard (§3.3): waves shorter than r·L, i.e. λ > √(2π/(k̂0 r L)), are dropped;
  // λ ≤ 2 is always kept (so that the main hump is never cut).
  const bool cut = s.short_wave_cutoff > 0.0;
  const double lambda_cut =
      cut ? std::max(2.0, std::sqrt(2.0 * std::numbers::pi / (k0_hat * s.short_wave_cutoff * s.cutoff_length))) : 0.0;

  // Initial range: well into the depth-decay regime (b T ≥ 5 at λ_max/4) and at least 4 periods.
  double lambda_max = std::max({8.0, 4.0 * std::sqrt(5.0 / (k0_hat * kochin.depth())), 1.0 + 4.0 * period});
  if (cut) lambda_max = lambda_cut;
  std::vector<Panel> panels;
  appendPanels(panels, 1.0, lambda_max, period);
  for (auto& p : panels) integrator.evaluate(p);
  auto total = [&] {
    double sum = 0;
    for (const auto& p : panels) sum += p.fine;
    return sum;
  };

  // Extend λ_max until the fitted tail is small (skipped when short waves are cut off).
  double tail = 0, exponent = 0;
  while (!cut) {
    const OctaveMean g1 = octaveMean(panels, 0.5 * lambda_max, lambda_max + 1e-12);
    const OctaveMean g2 = octaveMean(panels, 0.25 * lambda_max, 0.5 * lambda_max);
    const bool decaying = g1.mean > 0 && g2.mean > g1.mean;
    exponent = decaying ? std::log(g2.mean / g1.mean) / std::log(g1.lambda / g2.lambda) : 0.0;
    const double I = total();
    if (exponent > 1.5) {
      tail = g1.mean * std::pow(g1.lambda, exponent) * std::pow(lambda_max, 1.0 - exponent) / (exponent - 1.0);
      if (0.5 * tail <= 0.25 * s.relative_tolerance * (I + tail)) break;
    } else if (g1.mean == 0.0) {
      tail = 0;  // the integrand underflowed: nothing left beyond λ_max
      break;
    }
    if (integrator.evaluations > s.max_evaluations || lambda_max > 1e5) {
      r.converged = false;
      break;
    }
    const std::size_t first_new = panels.size();
    appendPanels(panels, lambda_max, 1.5 * lambda_max, period);
    for (std::size_t k = first_new; k < panels.size(); ++k) integrator.evaluate(panels[k]);
    lambda_max *= 1.5;
  }

  // Bisect the panel with the largest error estimate until the quadrature error meets its share.
  auto by_error = [&](std::size_t a, std::size_t b) { return panels[a].error < panels[b].error; };
  std::priority_queue<std::size_t, std::vector<std::size_t>, decltype(by_error)> worst(by_error);
  double quad_error = 0;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    worst.push(k);
    quad_error += panels[k].error;
  }
  while (quad_error > 0.5 * s.relative_tolerance * (total() + tail)) {
    if (integrator.evaluations > s.max_evaluations) {
      r.converged = false;
      break;
    }
    const std::size_t k = worst.top();
    worst.pop();
    Panel right = panels[k];
    const double mid = 0.5 * (panels[k].u0 + panels[k].u1);
    quad_error -= panels[k].error;
    panels[k].u1 = mid;
    right.u0 = mid;
    integrator.evaluate(panels[k]);
    integrator.evaluate(right);
    panels.push_back(right);
    quad_error += panels[k].error + right.error;
    worst.push(k);
    worst.push(panels.size() - 1);
  }

  double fine = 0, coarse = 0;
  for (const auto& p : panels) {
    fine += p.fine;
    coarse += p.coarse;
  }
  r.tail = prefactor * tail;
  r.resistance = prefactor * (fine + tail);
  r.quadrature_error = prefactor * quad_error;
  r.tail_error = 0.5 * r.tail;
  r.grid_error = kochin.hasCoarse() ? prefactor * std::abs(fine - coarse) / kochin.richardsonDivisor() : 0.0;
  r.error_estimate = r.quadrature_error + r.tail_error + r.grid_error;
  r.lambda_max = lambda_max;
  r.tail_exponent = exponent;
  r.evaluations = integrator.evaluations;
  r.panels = static_cast<int>(panels.size());
  return r;
}

std::vector<double> waveSpectrum(KochinFunction& kochin, double speed, double gravity, double density,
                                 const MichellSettings& s, const std::vector<double>& theta) {
  kochin.prepare(speed);
  const double k0 = gravity / (speed * speed);
  const double k0_hat = k0 * s.wave_number_factor;
  const double k_pre = s.prefactor_uses_corrected_wave_number ? k0_hat : k0;
  const double prefactor = 4.0 / std::numbers::pi * density * speed * speed * k_pre * k_pre;
  std::vector<double> out;
  out.reserve(theta.size());
  for (double t : theta) {
    const double sec = 1.0 / std::cos(t);
    double f = 0, c = 0;
    kochin.evaluate(k0_hat, sec, f, c);
    out.push_back(prefactor * f * sec * sec * sec);
  }
  return out;
}

}  // namespace maris::ship
