#include "tether/tether_vision.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/least_squares.hpp"
#include "core/portable_random.hpp"
#include "tether/tether_cable.hpp"

namespace maris::tether {

namespace {

constexpr double kMinDepth = 0.02;           // [m] points closer to the camera plane are not imaged
constexpr double kDegenerateSpread = 1e-3;   // [-] std dev of abscissas below which the image is a vertical line
constexpr int kMinPoints = 5;
constexpr int kMaxIterations = 50;
constexpr double kDerivativeStep = 1e-6;     // [-] central differences in (a, b)
constexpr double kRetryRms = 0.03;           // [-] rms residual above which the fit is retried from a grid

// Body (FLU) to camera (x right, y down, z forward).
Eigen::Vector3d bodyToCamera(const Eigen::Vector3d& body) { return {-body.y(), -body.z(), body.x()}; }

// Residual of one image point for features (a, b): y - y(x) where x back-projects onto the model tether, else the
// image distance to the nearer projected end of the tether (continuous at the ends), so that no point drops out
// of the cost and the fit cannot lower it by shortening the curve. False if (a, b) is not a model shape.
bool pointResidual(const TetherRig& rig, const Eigen::Vector3d& p2c, double rise, double a, double b,
                   const ImagePoint& p, double& residual) {
  double y = 0.0;
  if (modelOrdinate(rig, p2c, rise, a, b, p.x, y)) {
    residual = p.y - y;
    return true;
  }
  const Catenary c = catenaryFromShape(a * rig.sag_max, rise, rig.length);
  if (!c.fitsPaperModel() || !(std::abs(b) < 1.0)) return false;
  const double cos_a = std::sqrt(1.0 - b * b);
  const Eigen::Vector3d p1c(p2c.x() - c.span * b, p2c.y() - rise, p2c.z() + c.span * cos_a);
  double best = 1e300;
  for (const Eigen::Vector3d& end : {p2c, p1c})
    if (end.z() >= kMinDepth) best = std::min(best, std::hypot(p.x - end.x() / end.z(), p.y - end.y() / end.z()));
  if (best == 1e300) return false;
  residual = best;
  return true;
}

// Residuals of all points and (if jac) their (a, b) derivatives by central differences. Returns the number of points, or
// 0 when a stencil point is not a model shape.
int residuals(const TetherRig& rig, const Eigen::Vector3d& p2c, double rise, const std::vector<ImagePoint>& image,
              double a, double b, Eigen::VectorXd& r, Eigen::MatrixXd* jac) {
  const auto m = static_cast<Eigen::Index>(image.size());
  r.resize(m);
  if (jac) jac->resize(m, 2);
  const double h = kDerivativeStep;
  for (Eigen::Index j = 0; j < m; ++j) {
    const ImagePoint& p = image[static_cast<std::size_t>(j)];
    double r0, ra_plus, ra_minus, rb_plus, rb_minus;
    if (!pointResidual(rig, p2c, rise, a, b, p, r0)) return 0;
    r[j] = r0;
    if (!jac) continue;
    if (!pointResidual(rig, p2c, rise, a + h, b, p, ra_plus) || !pointResidual(rig, p2c, rise, a - h, b, p, ra_minus) ||
        !pointResidual(rig, p2c, rise, a, b + h, p, rb_plus) || !pointResidual(rig, p2c, rise, a, b - h, p, rb_minus))
      return 0;
    (*jac)(j, 0) = (ra_plus - ra_minus) / (2 * h);
    (*jac)(j, 1) = (rb_plus - rb_minus) / (2 * h);
  }
  return static_cast<int>(m);
}

// (a, b) and its finite-difference stencil are shapes of the paper's model.
bool insideBox(const TetherRig& rig, double a, double b, double rise, double margin) {
  const double d = (rise + rig.rise_max) / (2.0 * rig.rise_max);
  for (double da : {-margin, margin})
    for (double db : {-margin, margin})
      if (!featureInfeasibility(rig, Features{a + da, b + db, d, 0.0}).empty()) return false;
  return std::abs(b) + margin < 0.99;
}

// Levenberg–Marquardt (core/least_squares.hpp) on (a, b) from `est`, with the Jacobian by central differences;
// trial points stay in the feasible box by step halving. A point whose difference stencil leaves the model's
// shapes counts as undefined, so the Jacobian is formed with every residual and kept for the accepted point.
ShapeEstimate fitShape(const TetherRig& rig, const Eigen::Vector3d& p2c, double rise,
                       const std::vector<ImagePoint>& image, ShapeEstimate est) {
  Eigen::Vector2d jac_at(NAN, NAN);
  Eigen::MatrixXd jac_there;
  LeastSquaresProblem problem;
  problem.residuals = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    jac_at = x;
    const bool defined = residuals(rig, p2c, rise, image, x[0], x[1], r, &jac_there) >= kMinPoints;
    if (!defined) jac_at.setConstant(NAN);
    return defined;
  };
  problem.jacobian = [&](const Eigen::VectorXd& x, const Eigen::VectorXd&, Eigen::MatrixXd& jac) {
    Eigen::VectorXd r;
    if (x == Eigen::VectorXd(jac_at)) {
      jac = jac_there;
      return true;
    }
    return residuals(rig, p2c, rise, image, x[0], x[1], r, &jac) >= kMinPoints;
  };
  problem.trial_point = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& step) {
    double factor = 1.0;
    while (!insideBox(rig, x[0] + factor * step[0], x[1] + factor * step[1], rise, kDerivativeStep) && factor > 1e-6)
      factor *= 0.5;
    return Eigen::VectorXd(x + factor * step);
  };
  LeastSquaresOptions options;
  options.max_iterations = kMaxIterations;
  options.initial_damping = 1e-3;
  const LeastSquaresReport fit = levenbergMarquardt(problem, Eigen::Vector2d(est.a, est.b), options);
  est.points_used = fit.stop == LeastSquaresStop::InvalidStart ? 0 : static_cast<int>(fit.residuals.size());
  if (est.points_used < kMinPoints) return est;
  est.a = fit.x[0];
  est.b = fit.x[1];
  est.iterations = fit.iterations;
  est.converged = fit.converged;
  est.rms_residual = std::sqrt(fit.cost / est.points_used);
  return est;
}

}  // namespace

Eigen::Vector3d attachmentInCamera(const TetherRig& rig, const CameraModel& camera) {
  return bodyToCamera(rig.follower_attachment - camera.position_in_body);
}

std::vector<ImagePoint> projectTether(const CameraModel& camera, const RobotPose& follower,
                                      const std::vector<Eigen::Vector3d>& world_points, std::mt19937_64* noise) {
  const Eigen::Matrix3d world_to_body = Eigen::AngleAxisd(-follower.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const double limit = std::tan(camera.half_field_of_view);
  std::vector<ImagePoint> image;
  for (const auto& w : world_points) {
    const Eigen::Vector3d c = bodyToCamera(world_to_body * (w - follower.position) - camera.position_in_body);
    if (c.z() < kMinDepth) continue;
    ImagePoint p{c.x() / c.z(), c.y() / c.z()};
    if (std::abs(p.x) > limit || std::abs(p.y) > limit) continue;
    if (noise && camera.noise > 0.0) {
      p.x += camera.noise * standardNormal(*noise);
      p.y += camera.noise * standardNormal(*noise);
    }
    image.push_back(p);
  }
  return image;
}

bool modelOrdinate(const TetherRig& rig, const Eigen::Vector3d& p2c, double rise, double a, double b, double x,
                   double& y) {
  const Catenary c = catenaryFromShape(a * rig.sag_max, rise, rig.length);
  if (!c.fitsPaperModel() || !(std::abs(b) < 1.0)) return false;
  const double sin_a = b, cos_a = std::sqrt(1.0 - b * b);
  // A plane point at horizontal distance zeta has camera coordinates (cx2 - zeta sin, cy2 - h, cz2 + zeta cos);
  // its abscissa is x when zeta (x cos + sin) = cx2 - x cz2.
  const double denominator = x * cos_a + sin_a;
  if (std::abs(denominator) < 1e-12) return false;
  const double zeta = (p2c.x() - x * p2c.z()) / denominator;
  if (!(zeta >= 0.0 && zeta <= c.span)) return false;  // unbounded residual: outside the tether
  const double depth = p2c.z() + zeta * cos_a;
  if (depth < kMinDepth) return false;
  y = (p2c.y() - catenaryHeightAt(c, zeta)) / depth;
  return std::isfinite(y);
}

ShapeEstimate estimateShape(const TetherRig& rig, const CameraModel& camera, const std::vector<ImagePoint>& image,
                            double rise, const ShapeEstimate& start) {
  ShapeEstimate held = start;
  held.held = true;
  held.iterations = 0;
  held.points_used = static_cast<int>(image.size());
  // Degenerate view (paper eqs. 20-21): all points on one image column.
  if (static_cast<int>(image.size()) < kMinPoints) return held;
  double mean = 0.0, var = 0.0;
  for (const auto& p : image) mean += p.x;
  mean /= static_cast<double>(image.size());
  for (const auto& p : image) var += (p.x - mean) * (p.x - mean);
  if (std::sqrt(var / static_cast<double>(image.size())) < kDegenerateSpread) return held;

  const Eigen::Vector3d p2c = attachmentInCamera(rig, camera);
  ShapeEstimate est = start;
  est.held = false;
  if (!insideBox(rig, est.a, est.b, rise, kDerivativeStep))
    est.a = 0.5 * (0.5 * (rig.length - rise) + std::max(0.0, -rise)) / rig.sag_max;
  est = fitShape(rig, p2c, rise, image, est);
  // A poor fit (the paper starts from the lowest detected point; we have no image processing) is retried from the
  // best point of a coarse grid over the feasible box: the cost has local minima near b = 0, where the tether
  // plane passes close to the camera and the curve collapses to a vertical segment.
  if (est.points_used < kMinPoints || est.rms_residual > kRetryRms) {
    ShapeEstimate best = est;
    double best_cost = 1e300;
    Eigen::VectorXd r;
    for (int i = 1; i <= 20; ++i)
      for (int j = -19; j <= 19; ++j) {
        const double a = 1.5 * i / 20.0, b = j / 20.0;
        if (!insideBox(rig, a, b, rise, kDerivativeStep)) continue;
        const int n = residuals(rig, p2c, rise, image, a, b, r, nullptr);
        if (n >= kMinPoints && r.squaredNorm() / n < best_cost) {
          best_cost = r.squaredNorm() / n;
          best.a = a;
          best.b = b;
        }
      }
    const ShapeEstimate retry = fitShape(rig, p2c, rise, image, best);
    if (retry.points_used >= kMinPoints && (est.points_used < kMinPoints || retry.rms_residual < est.rms_residual))
      est = retry;
  }
  if (est.points_used < kMinPoints) return held;
  return est;
}

}  // namespace maris::tether
