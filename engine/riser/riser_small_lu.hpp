// The 3×3 LU with partial pivoting of the reaction sweep (riser_dynamics' block-Thomas solve), written out so that
// it does the same floating-point operations in the same order as Eigen 3.4's PartialPivLU<Matrix3d> and its
// solve() for a vector and for a 3×3 right side, and gives bit for bit the same results (test RiserRhsKernels
// compares them), without Eigen's general blocked triangular-solve kernel for the matrix right side, its packing
// and its L1 norm of the matrix (for rcond, unused here). Why bit for bit: the statics Newton of long chains
// counts its iterations on rounding of this solve (a cofactor inverse, equally accurate, took the 1000-link
// chain from 8 to 21 iterations).
// Eigen's operations, mirrored: pivot = the first entry of largest magnitude in the column (strict >), rows
// swapped whole, the column below divided by the pivot, the rank-1 update a_ij −= l_ik u_kj; a vector right side by
// the unrolled triangular solves (sums of two products added first, division by the diagonal); a matrix right side
// column by column by the blocked kernel's small-panel loop (unit lower: x_k scaled by 1, then b_i −= x_k l_ik;
// upper: x_k = b_k · (1/u_kk), then b_i −= x_k u_ik, from the last row up). No FMA: the build does not enable it.
#pragma once

#include <cmath>
#include <utility>

#include <Eigen/Core>

namespace maris::riser {

class SmallLu3 {
 public:
  explicit SmallLu3(const Eigen::Matrix3d& a) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) lu_[i][j] = a(i, j);
    for (int k = 0; k < 2; ++k) {
      int p = k;
      double biggest = std::abs(lu_[k][k]);
      for (int i = k + 1; i < 3; ++i)
        if (std::abs(lu_[i][k]) > biggest) {
          biggest = std::abs(lu_[i][k]);
          p = i;
        }
      swap_[k] = p;
      if (biggest != 0.0) {
        if (p != k) std::swap(lu_[k], lu_[p]);
        for (int i = k + 1; i < 3; ++i) lu_[i][k] /= lu_[k][k];
      }
      for (int j = k + 1; j < 3; ++j)
        for (int i = k + 1; i < 3; ++i) lu_[i][j] -= lu_[i][k] * lu_[k][j];
    }
  }

  Eigen::Vector3d solve(const Eigen::Vector3d& rhs) const {
    double b[3] = {rhs[0], rhs[1], rhs[2]};
    permute(b);
    const auto& a = lu_;
    b[1] -= a[1][0] * b[0];
    b[2] -= a[2][0] * b[0] + a[2][1] * b[1];
    b[2] /= a[2][2];
    b[1] -= a[1][2] * b[2];
    b[1] /= a[1][1];
    b[0] -= a[0][1] * b[1] + a[0][2] * b[2];
    b[0] /= a[0][0];
    return {b[0], b[1], b[2]};
  }

  Eigen::Matrix3d solve(const Eigen::Matrix3d& rhs) const {
    Eigen::Matrix3d x;
    const auto& a = lu_;
    const double r2 = 1.0 / a[2][2], r1 = 1.0 / a[1][1], r0 = 1.0 / a[0][0];
    for (int j = 0; j < 3; ++j) {
      double b[3] = {rhs(0, j), rhs(1, j), rhs(2, j)};
      permute(b);
      b[1] -= b[0] * a[1][0];
      b[2] -= b[0] * a[2][0];
      b[2] -= b[1] * a[2][1];
      b[2] *= r2;
      b[0] -= b[2] * a[0][2];
      b[1] -= b[2] * a[1][2];
      b[1] *= r1;
      b[0] -= b[1] * a[0][1];
      b[0] *= r0;
      x(0, j) = b[0], x(1, j) = b[1], x(2, j) = b[2];
    }
    return x;
  }

 private:
  void permute(double (&b)[3]) const {
    for (int k = 0; k < 2; ++k)
      if (swap_[k] != k) std::swap(b[k], b[swap_[k]]);
  }

  // Plain doubles: as an Eigen::Matrix3d the factors were stored one element at a time and read back two at a time
  // by Eigen's packet loads (a store-forwarding stall, by the annotated profile); with the sweep's products also in
  // scalars the right-hand side took 12 % less time, the same bits.
  double lu_[3][3];
  int swap_[2] = {0, 1};
};

}  // namespace maris::riser
