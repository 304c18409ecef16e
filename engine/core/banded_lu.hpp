// LU factorisation with partial pivoting of a banded square matrix (kl sub-diagonals, ku
// super-diagonals), as LAPACK's dgbtrf/dgbtrs do: row interchanges widen U to kl + ku
// super-diagonals, so storage is n × (2 kl + ku + 1) and work O(n·kl·(kl + ku)) instead of O(n³).
// Used by the generalized-α Newton iteration for chain-like systems (risers, tethers, cables).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace maris {

class BandedLu {
 public:
  // Sizes the storage for an n × n matrix with the given bandwidths and sets every entry to zero.
  void resize(Eigen::Index n, Eigen::Index lower_bandwidth, Eigen::Index upper_bandwidth);

  Eigen::Index size() const { return n_; }
  Eigen::Index lowerBandwidth() const { return kl_; }
  Eigen::Index upperBandwidth() const { return ku_; }

  // Entry (i, j) of the matrix before factorisation; |j − i| must lie inside the band (asserted).
  double& at(Eigen::Index i, Eigen::Index j);
  void setZero();

  // Factorises in place. Returns false if a pivot is zero or below 1e-14 × the largest entry
  // (numerically singular); solve() must not be called then.
  bool factorize();

  // Overwrites b with the solution of A x = b (A the matrix given before factorize()).
  void solve(Eigen::VectorXd& b) const;

 private:
  double& band(Eigen::Index i, Eigen::Index j) { return storage_(i, j - i + kl_); }
  double band(Eigen::Index i, Eigen::Index j) const { return storage_(i, j - i + kl_); }

  Eigen::Index n_ = 0, kl_ = 0, ku_ = 0;
  // Row i holds columns i − kl … i + kl + ku (fill-in included); row-major, so that the elimination's row updates and
  // the back substitution run along memory and the forward substitution's multipliers of one step lie within kl
  // consecutive rows (the solve of n = 909, kl = ku = 14 is called once per Newton iteration of the riser).
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> storage_;
  std::vector<Eigen::Index> pivot_rows_;   // row swapped with row k at elimination step k
};

}  // namespace maris
