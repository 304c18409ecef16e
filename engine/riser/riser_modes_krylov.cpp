// Shift-invert Arnoldi on the banded constrained pencil (method in riser_modes_krylov.hpp).
#include "riser/riser_modes_krylov.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Spectra/GenEigsSolver.h>

#include "core/abandonable.hpp"
#include "core/banded_lu.hpp"
#include "core/errors.hpp"
#include "core/text_format.hpp"
#include "riser/riser_dynamics.hpp"

namespace maris::riser {
namespace {

// Eigenvalues λ = ω² below kZeroMode × (largest diagonal K/M ratio, about the highest ω²) are the chain's free
// motions (a pinned chain spinning about its axis), dropped as computeModes drops them. Measured on the default
// riser: the free spin at |λ| ≈ 1e-16 of that scale, the lowest bending mode at 6e-7 (n = 50), 3e-9 (n = 500),
// 6e-10 (n = 1000), falling as n⁻⁴ (so about 1e-12 at n = 5000). computeModes' 1e-9 would drop real modes above n ≈ 400.
constexpr double kZeroMode = 1e-14;
// Shift σ = −kShift × that ratio: below every ω², so the pencil is regular even with free motions, and small enough
// not to slow convergence to the lowest modes (the Ritz values converge at rates (λ_k − σ)/(λ_{ncv} − σ)).
constexpr double kShift = 1e-12;
// Extra modes asked of Arnoldi beyond `count`: room for dropped free motions and for the second member of the
// pairs of equal frequency a straight chain has in 3D.
constexpr int kExtraModes = 6;

// The banded pencil of the dynamic segments and its factorised shift [K − σM, −B; C, 0].
class ChainPencil {
 public:
  ChainPencil(const RiserModel& m, const StaticSolution& statics, double step) : m_(m), statics_(statics), step_(step) {
    f_ = m.first_dynamic;
    segments_ = m.last_dynamic - m.first_dynamic + 1;
    s_ = m.torsion ? 6 : 5;
    block_ = 3 + s_;
    size_ = block_ * segments_ + 3;
    assemble();
  }

  int coordinates() const { return s_ * segments_; }
  double stiffnessScale() const { return scale_; }

  // Factorises the shifted matrix; false when it is singular.
  bool factorize(double sigma) {
    const int bw = 2 * s_ + 2;
    lu_.resize(size_, bw, bw);
    for (int k = 0; k < segments_; ++k) {
      for (int a = 0; a < s_; ++a) {
        const Eigen::Index row = segmentIndex(k) + a;
        for (int j = std::max(0, k - 1); j <= std::min(segments_ - 1, k + 1); ++j)
          for (int b = 0; b < s_; ++b)
            lu_.at(row, segmentIndex(j) + b) = stiffness_[k][j - k + 1](a, b) - (j == k ? sigma * mass_[k](a, b) : 0.0);
        // −Tᵀ B: F_k pushes the segment's origin (E), F_{k+1} pulls its far end (−D'_k).
        for (int c = 0; c < 3; ++c) {
          if (a < 3) {
            lu_.at(row, reactionIndex(k) + c) = a == c ? -m_.element_length : 0.0;
            lu_.at(row, reactionIndex(k + 1) + c) = a == c ? m_.element_length : 0.0;
          } else {
            lu_.at(row, reactionIndex(k + 1) + c) = far_moment_[k](a - 3, c);
          }
        }
      }
    }
    constraintRows([this](Eigen::Index i, Eigen::Index j, double v) { lu_.at(i, j) = v; });
    return lu_.factorize();
  }

  // y = the connected solution u of (K − σM) u − B μ = M x, C u = 0.
  void apply(const double* x, double* y) {
    rhs_.setZero(size_);
    for (int k = 0; k < segments_; ++k)
      rhs_.segment(segmentIndex(k), s_) = mass_[k] * Eigen::Map<const Eigen::VectorXd>(x + s_ * k, s_);
    lu_.solve(rhs_);
    for (int k = 0; k < segments_; ++k)
      Eigen::Map<Eigen::VectorXd>(y + s_ * k, s_) = rhs_.segment(segmentIndex(k), s_);
  }

  // u (segment by segment) in the order of appendAbsoluteMode: all positions, then all rotations.
  Eigen::VectorXd absoluteOrder(const Eigen::VectorXd& u) const {
    Eigen::VectorXd v(u.size());
    const int r = s_ - 3;
    for (int k = 0; k < segments_; ++k) {
      v.segment<3>(3 * k) = u.segment<3>(s_ * k);
      v.segment(3 * segments_ + r * k, r) = u.segment(s_ * k + 3, r);
    }
    return v;
  }

  // K, M and the constraint rows on the coordinates as dense matrices (DensePencil).
  DensePencil dense() const {
    const int n = coordinates();
    DensePencil out{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(3 * (segments_ + 1), n)};
    for (int k = 0; k < segments_; ++k) {
      out.mass.block(s_ * k, s_ * k, s_, s_) = mass_[k];
      for (int j = std::max(0, k - 1); j <= std::min(segments_ - 1, k + 1); ++j)
        out.stiffness.block(s_ * k, s_ * j, s_, s_) = stiffness_[k][j - k + 1];
    }
    // Band indices → constraint row (3 per reaction block) and coordinate column; reaction columns (known forces) dropped.
    constraintRows([&](Eigen::Index i, Eigen::Index j, double v) {
      if (j % block_ < 3) return;
      out.constraints(3 * (i / block_) + i % block_, s_ * (j / block_) + j % block_ - 3) = v;
    });
    return out;
  }

 private:
  Eigen::Index reactionIndex(int k) const { return static_cast<Eigen::Index>(block_) * k; }
  Eigen::Index segmentIndex(int k) const { return static_cast<Eigen::Index>(block_) * k + 3; }

  // Segment loads at fixed static reactions, g_i = b_i + E F⁰_i − D'_i F⁰_{i+1}, in the coordinates: Tᵀ g with
  // T = diag(Δ I, P_i) (positions scaled by Δ, rotations about the axes P_i).
  void loads(const Eigen::VectorXd& y, std::vector<Eigen::VectorXd>& out) {
    prepareSegments(m_, ws_, 0.0, y);
    out.resize(segments_);
    for (int k = 0; k < segments_; ++k) {
      const int i = f_ + k;
      const Vec3 d = m_.segments[i].length * ws_.pose.rotation[i].col(0);
      Vec6 g = ws_.bias[i];
      g.head<3>() += reaction_[i] - reaction_[i + 1];
      g.tail<3>() -= d.cross(reaction_[i + 1]);
      out[k].resize(s_);
      out[k].head<3>() = m_.element_length * g.head<3>();
      out[k].tail(s_ - 3) = axes_[k].transpose() * g.tail<3>();
    }
  }

  // State y0 with coordinate c of every third segment from `phase` moved by h.
  Eigen::VectorXd perturbed(int phase, int c, double h) const {
    Eigen::VectorXd y = y0_;
    for (int k = phase; k < segments_; k += 3) {
      const int i = f_ + k;
      if (c < 3) {
        y[segmentStateOffset(m_, i) + c] += h * m_.element_length;
        continue;
      }
      const Eigen::Index oq = orientationStateOffset(m_, i);
      const Eigen::Quaterniond q(y[oq], y[oq + 1], y[oq + 2], y[oq + 3]);
      const Eigen::Quaterniond turned =
          (Eigen::Quaterniond(Eigen::AngleAxisd(h, axes_[k].col(c - 3))) * q).normalized();
      y.segment<4>(oq) << turned.w(), turned.x(), turned.y(), turned.z();
    }
    return y;
  }

  void assemble() {
    ws_ = makeWorkspace(m_, 0.0);  // Baumgarte off, as computeModes
    y0_ = restState(m_, statics_.orientation, statics_.top);
    Eigen::VectorXd dy(y0_.size());
    evaluateRhs(m_, ws_, 0.0, y0_, dy);
    reaction_ = ws_.reaction;
    axes_.resize(segments_);
    mass_.resize(segments_);
    far_moment_.resize(segments_);
    arm_.resize(segments_);
    for (int k = 0; k < segments_; ++k) {
      const int i = f_ + k;
      const Mat3 r = statics_.orientation[i].toRotationMatrix();
      axes_[k] = m_.torsion ? Eigen::MatrixXd(Mat3::Identity()) : Eigen::MatrixXd(r.rightCols<2>());
      Eigen::MatrixXd t = Eigen::MatrixXd::Zero(6, s_);
      t.topLeftCorner<3, 3>() = m_.element_length * Mat3::Identity();
      t.bottomRightCorner(3, s_ - 3) = axes_[k];
      Mat6 rot = Mat6::Zero();
      rot.topLeftCorner<3, 3>() = r;
      rot.bottomRightCorner<3, 3>() = r;
      mass_[k] = t.transpose() * rot * m_.segments[i].mass_local * rot.transpose() * t;
      arm_[k] = m_.segments[i].length * r.col(0);
      far_moment_[k] = axes_[k].transpose() * skew(arm_[k]);  // Pᵀ [d]×: moment row of −Tᵀ(−D'_k)
    }
    // K = −∂(Tᵀ g)/∂u by central differences, every third segment at once (a segment's loads depend on its
    // neighbours' coordinates only): 6 s evaluations of O(n) each.
    stiffness_.assign(segments_, {Eigen::MatrixXd::Zero(s_, s_), Eigen::MatrixXd::Zero(s_, s_),
                                  Eigen::MatrixXd::Zero(s_, s_)});
    std::vector<Eigen::VectorXd> plus, minus;
    for (int phase = 0; phase < 3; ++phase)
      for (int c = 0; c < s_; ++c) {
        loads(perturbed(phase, c, step_), plus);
        loads(perturbed(phase, c, -step_), minus);
        for (int k = phase; k < segments_; k += 3)
          for (int j = std::max(0, k - 1); j <= std::min(segments_ - 1, k + 1); ++j)
            stiffness_[j][k - j + 1].col(c) = -(plus[j] - minus[j]) / (2 * step_);
      }
    scale_ = 0.0;
    for (int k = 0; k < segments_; ++k)
      for (int a = 0; a < s_; ++a) scale_ = std::max(scale_, std::abs(stiffness_[k][1](a, a)) / mass_[k](a, a));
  }

  // Rows of C (per reaction block): the held top components (or the known top force), the joints, the held
  // bottom (or its zero force); gaps divided by Δ. set(row, column, value) with the band's indices.
  template <class Set>
  void constraintRows(Set set) const {
    for (int c = 0; c < 3; ++c) {
      if (topForceKnown(m_, c))
        set(reactionIndex(0) + c, reactionIndex(0) + c, 1.0);
      else
        set(reactionIndex(0) + c, segmentIndex(0) + c, 1.0);
    }
    // Far end of segment k: δr_k/Δ + δψ_k × d_k/Δ = u_k − [d_k]× P_k a_k / Δ.
    auto far_end = [&](int row_block, int k) {
      const Eigen::MatrixXd turn = -skew(arm_[k]) * axes_[k] / m_.element_length;
      for (int c = 0; c < 3; ++c) {
        set(reactionIndex(row_block) + c, segmentIndex(k) + c, 1.0);
        for (int b = 0; b < s_ - 3; ++b) set(reactionIndex(row_block) + c, segmentIndex(k) + 3 + b, turn(c, b));
      }
    };
    for (int k = 1; k < segments_; ++k) {
      far_end(k, k - 1);
      for (int c = 0; c < 3; ++c) set(reactionIndex(k) + c, segmentIndex(k) + c, -1.0);
    }
    if (bottomHeld(m_)) {
      far_end(segments_, segments_ - 1);
    } else {
      for (int c = 0; c < 3; ++c) set(reactionIndex(segments_) + c, reactionIndex(segments_) + c, 1.0);
    }
  }

  const RiserModel& m_;
  const StaticSolution& statics_;
  int f_ = 0, segments_ = 0, s_ = 6, block_ = 9;
  Eigen::Index size_ = 0;
  double step_ = 1e-6;
  double scale_ = 0.0;
  RiserWorkspace ws_;
  Eigen::VectorXd y0_, rhs_;
  std::vector<Vec3> reaction_, arm_;
  std::vector<Eigen::MatrixXd> axes_, mass_, far_moment_;
  std::vector<std::array<Eigen::MatrixXd, 3>> stiffness_;  // K blocks of segment row k: columns k−1, k, k+1
  BandedLu lu_;
};

// Spectra's operator interface over the pencil, with the cancellation check between applications.
class ShiftInvertOperator {
 public:
  using Scalar = double;
  ShiftInvertOperator(ChainPencil& pencil, const RunContext& context) : pencil_(pencil), context_(context) {}
  Eigen::Index rows() const { return pencil_.coordinates(); }
  Eigen::Index cols() const { return pencil_.coordinates(); }
  void perform_op(const double* x_in, double* y_out) const {
    context_.throwIfCancelled();
    pencil_.apply(x_in, y_out);
  }

 private:
  ChainPencil& pencil_;
  const RunContext& context_;
};

// A real vector from a complex eigenvector of a real eigenvalue: turned so that its largest entry is real.
Eigen::VectorXd realMode(const Eigen::VectorXcd& x) {
  Eigen::Index largest = 0;
  x.cwiseAbs().maxCoeff(&largest);
  return (x * (std::conj(x[largest]) / std::abs(x[largest]))).real();
}

}  // namespace

DensePencil denseModesPencil(const RiserModel& model, const StaticSolution& statics, double difference_step) {
  const RiserModel m = modesModel(model, Formulation::Absolute);
  return ChainPencil(m, statics, difference_step).dense();
}

ModesMethod modesMethod(const RiserModel& model) {
  if (model.n <= kDenseModesMaxSegments) return ModesMethod::Dense;
  return model.flow_speed == 0.0 ? ModesMethod::Krylov : ModesMethod::None;
}

RiserModes computeModesKrylov(const RiserModel& model, const StaticSolution& statics, int count,
                              const RunContext& context, std::string* method, const KrylovSettings& settings) {
  if (model.flow_speed != 0.0) throw std::invalid_argument("computeModesKrylov: internal flow needs the dense solver");
  const RiserModel m = modesModel(model, Formulation::Absolute);
  ChainPencil pencil(m, statics, settings.difference_step);
  const double sigma = -kShift * pencil.stiffnessScale();
  if (!pencil.factorize(sigma))
    throw SolverError("natural frequencies (shift-invert Arnoldi)", 0.0, 0,
                      formatText("the constrained stiffness K − σM is singular at σ = %.3g 1/s²", sigma));
  ShiftInvertOperator op(pencil, context);
  const int dim = pencil.coordinates();
  const int nev = std::min(count + kExtraModes, dim - 2);
  const int ncv = std::min(dim, std::max(2 * nev + 1, nev + 20));
  Spectra::GenEigsSolver<ShiftInvertOperator> eigs(op, nev, ncv);
  eigs.init();
  const Eigen::Index converged = eigs.compute(Spectra::SortRule::LargestMagn, settings.max_restarts, settings.tolerance);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw SolverError("natural frequencies (shift-invert Arnoldi)", 0.0, static_cast<long>(eigs.num_iterations()),
                      formatText("%ld of %d Ritz values converged to %.0e after %ld restarts and %ld operator "
                                 "applications (n = %d)",
                                 static_cast<long>(converged), nev, settings.tolerance, static_cast<long>(eigs.num_iterations()),
                                 static_cast<long>(eigs.num_operations()), m.n));
  const Eigen::VectorXcd nu = eigs.eigenvalues();
  const Eigen::MatrixXcd vectors = eigs.eigenvectors();
  std::vector<std::pair<double, Eigen::Index>> found;
  for (Eigen::Index k = 0; k < nu.size(); ++k) {
    const std::complex<double> lambda = sigma + 1.0 / nu[k];
    if (lambda.real() > kZeroMode * pencil.stiffnessScale() && std::abs(lambda.imag()) < 1e-6 * lambda.real())
      found.push_back({std::sqrt(lambda.real()), k});
  }
  std::sort(found.begin(), found.end());
  RiserModes out;
  for (int c = 0; c < std::min<int>(count, static_cast<int>(found.size())); ++c)
    appendAbsoluteMode(m, statics, found[c].first, pencil.absoluteOrder(realMode(vectors.col(found[c].second))), out);
  if (method)
    *method = formatText("shift-invert Arnoldi (Spectra) on the banded absolute-coordinate pencil, %d coordinates, "
                         "%ld restarts, %ld operator applications",
                         dim, static_cast<long>(eigs.num_iterations()), static_cast<long>(eigs.num_operations()));
  return out;
}

RiserModes naturalModes(const RiserModel& model, const StaticSolution& statics, int count, RunContext& context,
                        std::string* method) {
  switch (modesMethod(model)) {
    case ModesMethod::Dense:
      if (method) *method = formatText("dense eigen solve of order %d (Eigen)", modesEigenOrder(model));
      // Eigen's dense solve cannot be interrupted: a cancelled run leaves it to finish on its own.
      return runAbandonable(context, [model, statics, count] { return computeModes(model, statics, count); });
    case ModesMethod::Krylov:
      return computeModesKrylov(model, statics, count, context, method);
    case ModesMethod::None:
      break;
  }
  if (method) *method = "not computed (internal flow above n = 199 needs the dense state-space solver)";
  return RiserModes{};
}

}  // namespace maris::riser
