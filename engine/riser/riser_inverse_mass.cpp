// Inverse mass turned to the global frame (contract in riser/riser_inverse_mass.hpp).
#include "riser/riser_inverse_mass.hpp"

namespace maris::riser {
namespace {

// (a, b, c) of block B (rows r, columns c of `local`) with B = a I + b e_x e_xᵀ + c [e_x]×.
Vec3 blockCoefficients(const Mat6& local, int row, int col) {
  const double a = local(row + 1, col + 1);
  return Vec3(a, local(row, col) - a, local(row + 2, col + 1));
}

Mat3 blockOf(const Vec3& k, const Vec3& e) {
  return k.x() * Mat3::Identity() + k.y() * e * e.transpose() + k.z() * skew(e);
}

}  // namespace

AxisymmetricInverseMass axisymmetricCoefficients(const Mat6& local) {
  return {blockCoefficients(local, 0, 0), blockCoefficients(local, 0, 3), blockCoefficients(local, 3, 3)};
}

bool axisymmetricInverseMass(const Mat6& local, AxisymmetricInverseMass& out) {
  out = axisymmetricCoefficients(local);
  const Vec3 e = Vec3::UnitX();
  const Mat3 tl = blockOf(out.translation, e), tr = blockOf(out.coupling, e), br = blockOf(out.rotation, e);
  const auto close = [](const Mat3& a, const Mat3& b) {
    return (a - b).cwiseAbs().maxCoeff() <= 1e-13 * b.cwiseAbs().maxCoeff();
  };
  return close(tl, local.topLeftCorner<3, 3>()) && close(tr, local.topRightCorner<3, 3>()) &&
         close(tr.transpose(), local.bottomLeftCorner<3, 3>()) && close(br, local.bottomRightCorner<3, 3>());
}

void rotateInverseMass(const AxisymmetricInverseMass& local, const Vec3& t, Mat6& w) {
  const Mat3 tt = t * t.transpose();
  const Vec3& a = local.translation;
  const Vec3& c = local.coupling;
  const Vec3& r = local.rotation;
  w.topLeftCorner<3, 3>() = a.y() * tt;
  w.topLeftCorner<3, 3>().diagonal().array() += a.x();
  w.bottomRightCorner<3, 3>() = r.y() * tt;
  w.bottomRightCorner<3, 3>().diagonal().array() += r.x();
  Mat3 coupling = c.y() * tt + c.z() * skew(t);
  coupling.diagonal().array() += c.x();
  w.topRightCorner<3, 3>() = coupling;
  w.bottomLeftCorner<3, 3>() = coupling.transpose();
}

}  // namespace maris::riser
