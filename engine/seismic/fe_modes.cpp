#include "seismic/fe_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include "core/errors.hpp"
#include "seismic/fe_modes_detail.hpp"

namespace maris::seismic {

namespace detail {

DofMap numberDofs(const FeModel& model, bool fixed_base) {
  const FeMesh& m = model.mesh;
  DofMap d;
  d.of_node.assign(m.nodeCount(), -1);
  for (int a = 0; a < m.nodeCount(); ++a) {
    if (model.solid_mass[a] <= 0.0 || (fixed_base && a <= m.nx)) continue;
    d.of_node[a] = d.count;
    d.count += 2;
    d.mass.insert(d.mass.end(), {model.solid_mass[a], model.solid_mass[a]});
  }
  return d;
}

// K over the free dofs: per-cell 8×8 blocks plus the boundary springs.
Eigen::SparseMatrix<double> assembleStiffness(const FeModel& model, const DofMap& d) {
  const FeMesh& m = model.mesh;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(model.solid_cells.size() * 64 + d.count);
  for (int c : model.solid_cells) {
    int n[4];
    cellNodes(m, c, n);
    const ElementMatrix8& k = model.solid_stiffness[m.cell_material[c]];
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        if (d.of_node[n[a]] < 0 || d.of_node[n[b]] < 0) continue;
        for (int p = 0; p < 2; ++p)
          for (int q = 0; q < 2; ++q) t.emplace_back(d.of_node[n[a]] + p, d.of_node[n[b]] + q, k(2 * a + p, 2 * b + q));
      }
  }
  for (int a = 0; a < m.nodeCount(); ++a) {
    if (d.of_node[a] < 0) continue;
    t.emplace_back(d.of_node[a], d.of_node[a], model.spring_x[a]);
    t.emplace_back(d.of_node[a] + 1, d.of_node[a] + 1, model.spring_y[a]);
  }
  Eigen::SparseMatrix<double> k(d.count, d.count);
  k.setFromTriplets(t.begin(), t.end());
  return k;
}

// Shares of Σ m|u|² by material, effective masses: the diagnostics of one mode.
void describeMode(const FeModel& model, const DofMap& d, const Eigen::VectorXd& x, SolidMode& mode) {
  const FeMesh& m = model.mesh;
  double total = 0.0, horizontal = 0.0, px = 0.0, py = 0.0, mass = 0.0;
  for (int k = 0; k < d.count; k += 2) {
    total += d.mass[k] * (x[k] * x[k] + x[k + 1] * x[k + 1]);
    horizontal += d.mass[k] * x[k] * x[k];
    px += d.mass[k] * x[k];
    py += d.mass[k] * x[k + 1];
  }
  for (double node_mass : model.solid_mass) mass += node_mass;  // clamped nodes included
  mode.ux.assign(m.nodeCount(), 0.0);
  mode.uy.assign(m.nodeCount(), 0.0);
  if (!(total > 0.0)) return;  // a water-only mode of the coupled analysis: no solid motion to describe
  double reef = 0.0, top = 0.0, cells = 0.0;
  for (int c : model.solid_cells) {
    int n[4];
    cellNodes(m, c, n);
    double e = 0.0;
    for (int a : n)
      if (d.of_node[a] >= 0) e += std::pow(x[d.of_node[a]], 2) + std::pow(x[d.of_node[a] + 1], 2);
    e *= m.solids[m.cell_material[c]].density;
    cells += e;
    if (m.cell_material[c] >= 1) reef += e;
    if (m.cell_material[c] == 1) top += e;
  }
  mode.horizontal_share = horizontal / total;
  mode.reef_share = cells > 0.0 ? reef / cells : 0.0;
  mode.top_layer_share = cells > 0.0 ? top / cells : 0.0;
  mode.mass_ratio_x = px * px / total / mass;
  mode.mass_ratio_y = py * py / total / mass;
  double peak = 0.0;
  for (int k = 0; k < d.count; ++k) peak = std::max(peak, std::abs(x[k]));
  for (int a = 0; a < m.nodeCount(); ++a)
    if (d.of_node[a] >= 0) {
      mode.ux[a] = x[d.of_node[a]] / peak;
      mode.uy[a] = x[d.of_node[a] + 1] / peak;
    }
}

}  // namespace detail

using namespace detail;

ModalResult computeSolidModes(const FeModel& model, int count, bool fixed_base, RunContext& ctx) {
  ctx.progress(0.0, "modal analysis: factorising K");
  const DofMap d = numberDofs(model, fixed_base);
  ModalResult out;
  out.dof = d.count;
  if (count <= 0 || d.count == 0) return out;
  count = std::min(count, d.count);
  const Eigen::SparseMatrix<double> k = assembleStiffness(model, d);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(k);
  if (solver.info() != Eigen::Success || solver.vectorD().minCoeff() <= 0.0)
    throw SolverError("modal analysis", 0.0, 0,
                      "the stiffness matrix of the solid is not positive definite (no base and no boundary springs?)");
  const Eigen::Map<const Eigen::VectorXd> mass(d.mass.data(), d.count);

  // Lanczos on K⁻¹M in the M-inner product, full re-orthogonalisation (twice: "twice is enough").
  const int max_steps = std::min(d.count, 4 * count + 100);
  Eigen::MatrixXd v(d.count, max_steps + 1);
  std::vector<double> alpha, beta;
  Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(d.count, 1.0, 2.0);  // deterministic, not orthogonal to low modes
  w /= std::sqrt(w.dot(mass.cwiseProduct(w)));
  v.col(0) = w;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz;
  int steps = 0;
  for (int j = 0; j < max_steps; ++j) {
    ctx.throwIfCancelled();
    ctx.progress(static_cast<double>(j) / max_steps, "modal analysis: Lanczos");
    w = solver.solve(mass.cwiseProduct(v.col(j)));
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd proj = v.leftCols(j + 1).transpose() * mass.cwiseProduct(w);
      if (pass == 0) alpha.push_back(proj[j]);
      w -= v.leftCols(j + 1) * proj;
    }
    const double b = std::sqrt(std::max(0.0, w.dot(mass.cwiseProduct(w))));
    steps = j + 1;
    // Converged when the Ritz residual bounds |β s_last| of the `count` largest θ are tiny.
    bool converged = b < 1e-300;
    if ((steps >= count && steps % 10 == 0) || converged || steps == max_steps) {
      Eigen::MatrixXd t = Eigen::MatrixXd::Zero(steps, steps);
      for (int i = 0; i < steps; ++i) {
        t(i, i) = alpha[i];
        if (i + 1 < steps) t(i, i + 1) = t(i + 1, i) = beta[i];
      }
      ritz.compute(t);
      double worst = 0.0;
      for (int i = std::max(0, steps - count); i < steps; ++i)
        worst = std::max(worst, std::abs(b * ritz.eigenvectors()(steps - 1, i)) / ritz.eigenvalues()[i]);
      converged = converged || worst < 1e-10;
    }
    if (converged || steps == max_steps) break;
    beta.push_back(b);
    v.col(j + 1) = w / b;
  }
  out.lanczos_steps = steps;
  count = std::min(count, steps);

  // Ritz pairs: θ = 1/ω², largest first; the true residual is measured, not estimated.
  for (int i = steps - 1; i >= steps - count; --i) {
    const double lambda = 1.0 / ritz.eigenvalues()[i];
    const Eigen::VectorXd x = v.leftCols(steps) * ritz.eigenvectors().col(i);
    const Eigen::VectorXd kx = k * x;
    SolidMode mode;
    mode.frequency = std::sqrt(lambda) / (2.0 * std::numbers::pi);
    mode.residual = (kx - lambda * mass.cwiseProduct(x)).norm() / kx.norm();
    describeMode(model, d, x, mode);
    out.modes.push_back(std::move(mode));
  }
  ctx.progress(1.0, "modal analysis");
  return out;
}

}  // namespace maris::seismic
