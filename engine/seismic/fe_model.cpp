#include "seismic/fe_model.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace maris::seismic {

namespace {

// 2×2 Gauss integration of the bilinear square: K_λ = ∫Bᵀ m mᵀ B, K_μ = ∫Bᵀ diag(2,2,1) B,
// K_φ = ∫∇N·∇N. All three are independent of the side Δ in 2D.
void squareElementMatrices(double delta, ElementMatrix8& k_lambda, ElementMatrix8& k_mu, Eigen::Matrix4d& k_scalar) {
  const double xi_a[4] = {-1, 1, 1, -1}, eta_a[4] = {-1, -1, 1, 1};
  const double g = 1.0 / std::sqrt(3.0);
  const double det_j = 0.25 * delta * delta;
  k_lambda.setZero();
  k_mu.setZero();
  k_scalar.setZero();
  for (double xi : {-g, g}) {
    for (double eta : {-g, g}) {
      Eigen::Matrix<double, 3, 8> b = Eigen::Matrix<double, 3, 8>::Zero();
      Eigen::Matrix<double, 2, 4> grad;
      for (int a = 0; a < 4; ++a) {
        const double dx = (2.0 / delta) * 0.25 * xi_a[a] * (1.0 + eta_a[a] * eta);
        const double dy = (2.0 / delta) * 0.25 * eta_a[a] * (1.0 + xi_a[a] * xi);
        grad(0, a) = dx;
        grad(1, a) = dy;
        b(0, 2 * a) = dx;
        b(1, 2 * a + 1) = dy;
        b(2, 2 * a) = dy;
        b(2, 2 * a + 1) = dx;
      }
      const Eigen::Vector3d m(1, 1, 0);
      const Eigen::Matrix<double, 1, 8> mb = m.transpose() * b;
      k_lambda += det_j * mb.transpose() * mb;
      k_mu += det_j * b.transpose() * Eigen::Vector3d(2, 2, 1).asDiagonal() * b;
      k_scalar += det_j * grad.transpose() * grad;
    }
  }
}

}  // namespace

FeModel buildFeModel(const FeMesh& mesh) {
  FeModel f;
  f.mesh = mesh;
  const FeMesh& m = f.mesh;
  const int nn = m.nodeCount();
  const double d = m.delta, quarter_area = 0.25 * d * d;

  ElementMatrix8 k_lambda, k_mu;
  squareElementMatrices(d, k_lambda, k_mu, f.water_stiffness);
  double omega2_max = 0.0;  // element (Irons) bound on ω_max²
  for (const auto& s : m.solids) {
    f.solid_stiffness.push_back(s.lameLambda() * k_lambda + s.shearModulus() * k_mu);
    const double k_max = Eigen::SelfAdjointEigenSolver<ElementMatrix8>(f.solid_stiffness.back()).eigenvalues().maxCoeff();
    omega2_max = std::max(omega2_max, k_max / (s.density * quarter_area));
  }

  // Lumped masses.
  f.solid_mass.assign(nn, 0.0);
  f.water_mass.assign(nn, 0.0);
  bool any_water = false;
  for (int c = 0; c < m.cellCount(); ++c) {
    int n[4];
    cellNodes(m, c, n);
    if (m.cell_kind[c] == CellKind::Solid) {
      f.solid_cells.push_back(c);
      for (int a : n) f.solid_mass[a] += m.solids[m.cell_material[c]].density * quarter_area;
    } else if (m.cell_kind[c] == CellKind::Water) {
      any_water = true;
      f.water_cells.push_back(c);
      const double c2 = m.water.sound_speed * m.water.sound_speed;
      for (int a : n) f.water_mass[a] += quarter_area / c2;
    }
  }
  if (any_water) {
    const double k_max = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(f.water_stiffness).eigenvalues().maxCoeff();
    omega2_max = std::max(omega2_max, k_max * m.water.sound_speed * m.water.sound_speed / quarter_area);
  }

  // Free surface, fluid–solid coupling.
  f.water_fixed.assign(nn, 0);
  f.coupling.assign(nn, Eigen::Vector2d::Zero());
  for (int c : f.water_cells) {
    const int i = c % m.nx, j = c / m.nx;
    int n[4];
    cellNodes(m, c, n);
    if (m.kindAt(i, j + 1) == CellKind::Void) f.water_fixed[n[2]] = f.water_fixed[n[3]] = 1;
    auto couple = [&](int i2, int j2, int a, int b, Eigen::Vector2d n_f) {
      if (m.kindAt(i2, j2) != CellKind::Solid) return;
      f.coupling[a] += 0.5 * d * n_f;
      f.coupling[b] += 0.5 * d * n_f;
    };
    couple(i + 1, j, n[1], n[2], {1, 0});
    couple(i - 1, j, n[0], n[3], {-1, 0});
    couple(i, j - 1, n[0], n[1], {0, -1});
    couple(i, j + 1, n[3], n[2], {0, 1});
  }

  // Absorbing boundaries on the left, right and bottom edges.
  f.spring_x.assign(nn, 0.0);
  f.spring_y.assign(nn, 0.0);
  f.dashpot_x.assign(nn, 0.0);
  f.dashpot_y.assign(nn, 0.0);
  f.water_damping.assign(nn, 0.0);
  f.water_spring.assign(nn, 0.0);
  auto distance = [&](int node) {
    const int i = node % (m.nx + 1), j = node / (m.nx + 1);
    return std::max(std::hypot(m.nodeX(i), m.nodeY(j)), d);
  };
  auto solidEdge = [&](int cell, int a, int b, bool normal_is_x) {
    const ElasticMaterial& s = m.solids[m.cell_material[cell]];
    for (int node : {a, b}) {
      const double g_over_r = s.shearModulus() / distance(node), half = 0.5 * d;
      double& kn = normal_is_x ? f.spring_x[node] : f.spring_y[node];
      double& kt = normal_is_x ? f.spring_y[node] : f.spring_x[node];
      double& cn = normal_is_x ? f.dashpot_x[node] : f.dashpot_y[node];
      double& ct = normal_is_x ? f.dashpot_y[node] : f.dashpot_x[node];
      kn += kAlphaNormal * g_over_r * half;
      kt += kAlphaTangential * g_over_r * half;
      cn += s.density * s.vp * half;
      ct += s.density * s.vs * half;
    }
  };
  auto waterEdge = [&](int a, int b) {
    for (int node : {a, b}) {
      f.water_damping[node] += 0.5 * d / m.water.sound_speed;
      f.water_spring[node] += 0.5 * d / (2.0 * distance(node));
    }
  };
  for (int i = 0; i < m.nx; ++i) {
    const int c = i;  // bottom row is seabed
    const int right = m.periodic_x && i == m.nx - 1 ? m.node(0, 0) : m.node(i + 1, 0);
    if (m.cell_kind[c] == CellKind::Solid) solidEdge(c, m.node(i, 0), right, false);
  }
  for (int j = 0; j < m.ny && !m.periodic_x; ++j) {
    for (int side = 0; side < 2; ++side) {
      const int i = side == 0 ? 0 : m.nx - 1, edge_i = side == 0 ? 0 : m.nx;
      const int c = j * m.nx + i;
      if (m.cell_kind[c] == CellKind::Solid) solidEdge(c, m.node(edge_i, j), m.node(edge_i, j + 1), true);
      if (m.cell_kind[c] == CellKind::Water) waterEdge(m.node(edge_i, j), m.node(edge_i, j + 1));
    }
  }
  // Boundary springs add at most max(k/m) to ω² (sum of positive semi-definite parts).
  double spring_omega2 = 0.0;
  for (int a = 0; a < nn; ++a)
    if (f.solid_mass[a] > 0.0)
      spring_omega2 = std::max(spring_omega2, std::max(f.spring_x[a], f.spring_y[a]) / f.solid_mass[a]);
  omega2_max += spring_omega2;
  f.stable_step = 2.0 / std::sqrt(omega2_max);

  // Boundary substructure sets.
  std::vector<std::uint8_t> in_layer(nn, 0);
  for (int c = 0; c < m.cellCount(); ++c) {
    const int i = c % m.nx, j = c / m.nx;
    const bool lateral = !m.periodic_x && (i == 0 || i == m.nx - 1);
    if (m.cell_kind[c] == CellKind::Void || !(lateral || j == 0)) continue;
    (m.cell_kind[c] == CellKind::Solid ? f.layer_solid_cells : f.layer_water_cells).push_back(c);
    int n[4];
    cellNodes(m, c, n);
    for (int a : n) in_layer[a] = 1;
  }
  for (int a = 0; a < nn; ++a) {
    if (!in_layer[a]) continue;
    f.layer_nodes.push_back(a);
    const int i = a % (m.nx + 1), j = a / (m.nx + 1);
    if ((!m.periodic_x && (i == 0 || i == m.nx)) || j == 0) f.boundary_nodes.push_back(a);
  }
  return f;
}

void addSolidInternalForces(const FeModel& model, const std::vector<int>& cells, const std::vector<double>& ux,
                            const std::vector<double>& uy, std::vector<double>& fx, std::vector<double>& fy) {
  const FeMesh& m = model.mesh;
  Eigen::Matrix<double, 8, 1> u, r;
  for (int c : cells) {
    int n[4];
    cellNodes(m, c, n);
    for (int a = 0; a < 4; ++a) {
      u(2 * a) = ux[n[a]];
      u(2 * a + 1) = uy[n[a]];
    }
    r.noalias() = model.solid_stiffness[m.cell_material[c]] * u;
    for (int a = 0; a < 4; ++a) {
      fx[n[a]] -= r(2 * a);
      fy[n[a]] -= r(2 * a + 1);
    }
  }
}

void addWaterInternalForces(const FeModel& model, const std::vector<int>& cells, const std::vector<double>& phi,
                            std::vector<double>& fphi) {
  const FeMesh& m = model.mesh;
  Eigen::Vector4d v, r;
  for (int c : cells) {
    int n[4];
    cellNodes(m, c, n);
    for (int a = 0; a < 4; ++a) v(a) = phi[n[a]];
    r.noalias() = model.water_stiffness * v;
    for (int a = 0; a < 4; ++a) fphi[n[a]] -= r(a);
  }
}

}  // namespace maris::seismic
