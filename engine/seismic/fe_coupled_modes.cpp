// Fluid–solid natural modes of the reef, seabed and water (fe_modes.hpp, computeCoupledModes):
// shift-invert Arnoldi on the non-symmetric u–φ pencil, whose inverse needs only the SPD
// factorisations of the solid and water stiffness (the pencil's K is block lower triangular).
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include "core/errors.hpp"
#include "seismic/fe_modes_detail.hpp"
#include "core/text_format.hpp"

namespace maris::seismic {

using namespace detail;

namespace {

// Water unknowns: φ at every node with water mass that is not on the free surface.
struct WaterDofs {
  std::vector<int> of_node;  // −1 if none
  std::vector<int> node;     // node of each dof
  Eigen::VectorXd mass;      // [s^2] lumped ∫N/c²
  int count = 0;
};

WaterDofs numberWaterDofs(const FeModel& model) {
  WaterDofs w;
  w.of_node.assign(model.mesh.nodeCount(), -1);
  for (int a = 0; a < model.mesh.nodeCount(); ++a)
    if (model.water_mass[a] > 0.0 && !model.water_fixed[a]) {
      w.of_node[a] = w.count++;
      w.node.push_back(a);
    }
  w.mass.resize(w.count);
  for (int k = 0; k < w.count; ++k) w.mass[k] = model.water_mass[w.node[k]];
  return w;
}

// K_f = Σ cells ∫∇N·∇N + the radiation boundary's stiffness A/(2R) (per m thickness).
Eigen::SparseMatrix<double> assembleWaterStiffness(const FeModel& model, const WaterDofs& w) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(model.water_cells.size() * 16 + w.count);
  for (int c : model.water_cells) {
    int n[4];
    cellNodes(model.mesh, c, n);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (w.of_node[n[a]] >= 0 && w.of_node[n[b]] >= 0)
          t.emplace_back(w.of_node[n[a]], w.of_node[n[b]], model.water_stiffness(a, b));
  }
  for (int k = 0; k < w.count; ++k) t.emplace_back(k, k, model.water_spring[w.node[k]]);
  Eigen::SparseMatrix<double> k(w.count, w.count);
  k.setFromTriplets(t.begin(), t.end());
  return k;
}

// Q: solid dof (node a, x or y) × water dof (node a) = q_a (lumped per node).
Eigen::SparseMatrix<double> assembleCoupling(const FeModel& model, const DofMap& d, const WaterDofs& w) {
  std::vector<Eigen::Triplet<double>> t;
  for (int a = 0; a < model.mesh.nodeCount(); ++a) {
    if (d.of_node[a] < 0 || w.of_node[a] < 0 || model.coupling[a].squaredNorm() == 0.0) continue;
    t.emplace_back(d.of_node[a], w.of_node[a], model.coupling[a].x());
    t.emplace_back(d.of_node[a] + 1, w.of_node[a], model.coupling[a].y());
  }
  Eigen::SparseMatrix<double> q(d.count, w.count);
  q.setFromTriplets(t.begin(), t.end());
  return q;
}

}  // namespace

ModalResult computeCoupledModes(const FeModel& model, int count, bool fixed_base, RunContext& ctx) {
  ctx.progress(0.0, "modal analysis (with water): factorising K");
  const DofMap d = numberDofs(model, fixed_base);
  const WaterDofs w = numberWaterDofs(model);
  ModalResult out;
  const int ns = d.count, n = d.count + w.count;
  out.dof = n;
  if (count <= 0 || w.count == 0) return w.count == 0 ? computeSolidModes(model, count, fixed_base, ctx) : out;
  count = std::min(count, n);
  const double rho = model.mesh.water.density;
  const Eigen::SparseMatrix<double> ks = assembleStiffness(model, d), kf = assembleWaterStiffness(model, w);
  const Eigen::SparseMatrix<double> q = assembleCoupling(model, d, w);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solid(ks), water(kf);
  if (solid.info() != Eigen::Success || solid.vectorD().minCoeff() <= 0.0 || water.info() != Eigen::Success ||
      water.vectorD().minCoeff() <= 0.0)
    throw SolverError("modal analysis", 0.0, 0, "the solid or water stiffness matrix is not positive definite");
  const Eigen::Map<const Eigen::VectorXd> ms(d.mass.data(), ns);

  // Operator x ↦ K⁻¹M x and the products K x, M x for residuals.
  auto applyInverse = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd y(n);
    y.head(ns) = solid.solve(ms.cwiseProduct(x.head(ns)) + rho * (q * x.tail(w.count)));
    y.tail(w.count) = water.solve(w.mass.cwiseProduct(x.tail(w.count)) + q.transpose() * y.head(ns));
    return y;
  };
  Eigen::VectorXd weight(n);
  weight.head(ns) = ms;
  weight.tail(w.count) = rho * kf.diagonal();

  // Arnoldi in the weighted inner product, full re-orthogonalisation (twice).
  const int max_steps = std::min(n, 6 * count + 120);
  Eigen::MatrixXd v(n, max_steps + 1);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(max_steps + 1, max_steps);
  Eigen::VectorXd x0 = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  v.col(0) = x0 / std::sqrt(x0.dot(weight.cwiseProduct(x0)));
  Eigen::EigenSolver<Eigen::MatrixXd> ritz;
  Eigen::MatrixXcd ritz_vectors;
  std::vector<int> order;
  int steps = 0;
  bool converged = false;
  for (int j = 0; j < max_steps && !converged; ++j) {
    ctx.throwIfCancelled();
    ctx.progress(static_cast<double>(j) / max_steps, "modal analysis (with water): Arnoldi");
    Eigen::VectorXd y = applyInverse(v.col(j));
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd proj = v.leftCols(j + 1).transpose() * weight.cwiseProduct(y);
      h.col(j).head(j + 1) += proj;
      y -= v.leftCols(j + 1) * proj;
    }
    h(j + 1, j) = std::sqrt(std::max(0.0, y.dot(weight.cwiseProduct(y))));
    steps = j + 1;
    const bool breakdown = h(j + 1, j) < 1e-300;
    if ((steps >= count && steps % 10 == 0) || breakdown || steps == max_steps) {
      ritz.compute(h.topLeftCorner(steps, steps));
      order.resize(steps);
      for (int i = 0; i < steps; ++i) order[i] = i;
      std::sort(order.begin(), order.end(),
                [&](int a, int b) { return ritz.eigenvalues()[a].real() > ritz.eigenvalues()[b].real(); });
      // Ritz residual estimate |h_{m+1,m} y_m| relative to θ for the `count` largest θ.
      ritz_vectors = ritz.eigenvectors();  // returned by value: keep one copy
      double worst = 0.0;
      for (int i = 0; i < std::min(count, steps); ++i) {
        const auto yv = ritz_vectors.col(order[i]);
        worst = std::max(worst, h(j + 1, j) * std::abs(yv[steps - 1]) / yv.norm() /
                                    std::abs(ritz.eigenvalues()[order[i]]));
      }
      converged = breakdown || worst < 1e-10;
    }
    if (!breakdown) v.col(j + 1) = y / h(j + 1, j);
    else break;
  }
  out.lanczos_steps = steps;
  count = std::min(count, steps);

  // Ritz pairs: θ = 1/ω² (real for this conservative system); true residuals measured.
  for (int i = 0; i < count; ++i) {
    const std::complex<double> theta = ritz.eigenvalues()[order[i]];
    if (!(theta.real() > 0.0) || std::abs(theta.imag()) > 1e-6 * std::abs(theta))
      throw SolverError("modal analysis", 0.0, 0,
                        "a fluid–solid Ritz value stayed complex or non-positive (" + numberText(theta.real()) +
                            " + " + numberText(theta.imag()) + "i): the Arnoldi iteration did not converge");
    Eigen::VectorXcd yc = ritz_vectors.col(order[i]);
    Eigen::Index big;
    yc.cwiseAbs().maxCoeff(&big);
    yc *= std::conj(yc[big]) / std::abs(yc[big]);  // remove the arbitrary complex phase
    const Eigen::VectorXd x = v.leftCols(steps) * yc.real();
    const double lambda = 1.0 / theta.real();
    const Eigen::VectorXd u = x.head(ns), phi = x.tail(w.count);
    Eigen::VectorXd kx(n), mx(n);
    kx.head(ns) = ks * u;
    kx.tail(w.count) = kf * phi - q.transpose() * u;
    mx.head(ns) = ms.cwiseProduct(u) + rho * (q * phi);
    mx.tail(w.count) = w.mass.cwiseProduct(phi);
    SolidMode mode;
    mode.frequency = std::sqrt(lambda) / (2.0 * std::numbers::pi);
    mode.residual = (kx - lambda * mx).norm() / kx.norm();
    const double solid_energy = u.dot(ms.cwiseProduct(u)), water_energy = rho * phi.dot(kf * phi);
    mode.water_share = water_energy / (solid_energy + water_energy);
    describeMode(model, d, u, mode);
    out.modes.push_back(std::move(mode));
  }
  std::sort(out.modes.begin(), out.modes.end(), [](const auto& a, const auto& b) { return a.frequency < b.frequency; });
  ctx.progress(1.0, "modal analysis (with water)");
  return out;
}

}  // namespace maris::seismic
