#include "riser/riser_statics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>
#include <Eigen/QR>

#include "core/errors.hpp"
#include "core/least_squares.hpp"
#include "core/text_format.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_joint_newton.hpp"
#include "riser/riser_relaxation.hpp"

namespace maris::riser {
namespace {

struct Configuration {
  std::vector<Eigen::Quaterniond> orientation;
  Vec3 top = Vec3::Zero();
  Vec3 end_reaction = Vec3::Zero();
};

constexpr double kTolerance = 1e-11;  // scaled residual (forces / F_ref, lengths / L), at most n ≤ 210

class StaticProblem {
 public:
  explicit StaticProblem(const RiserModel& model) : m_(model), ws_(makeWorkspace(model, 0.0)) {
    m_.formulation = Formulation::Joint;  // statics always in joint coordinates
    for (int c = 0; c < 3; ++c)
      if (topForceKnown(m_, c)) top_free_.push_back(c);
    rotation_dofs_ = m_.torsion ? 3 : 2;
    // The scaled residual sums the forces of up to n segments and their moments over n lever arms: its
    // round-off floor grows like n²·ε (measured on a 100 m riser: 2.8e-13 at n = 100, 1.8e-11 at n = 1000), so
    // above n ≈ 210 the tolerance is n²·ε rather than an unreachable 1e-11.
    const double segments = m_.n + 1;
    tolerance_ = std::max(kTolerance, std::numeric_limits<double>::epsilon() * segments * segments);
    size_ = static_cast<int>(top_free_.size()) + rotation_dofs_ * (m_.last_dynamic - m_.first_dynamic + 1) +
            (bottomHeld(m_) ? 3 : 0);
    // Reference force for scaling: weight, tension, point loads, drag and spring stiffness.
    force_ref_ = m_.top_tension;
    if (m_.axial_stiffness > 0) force_ref_ += std::abs(knownTopForce(m_, 2, 0.0, m_.initial_top, Vec3::Zero()));
    for (int i = 0; i <= m_.n; ++i) {
      const Segment& s = m_.segments[i];
      const double v = m_.current_profile.max_speed;
      force_ref_ += (s.weight_per_length + s.buoyancy_per_length + s.normal_drag * v * v) * s.length;
      force_ref_ += m_.joints[i].stiffness.maxCoeff() / m_.length;
    }
    for (const auto& l : m_.point_loads)
      force_ref_ += Vec3(l.force_x, l.force_y, l.force_z).norm() + Vec3(l.moment_x, l.moment_y, l.moment_z).norm() / m_.length;
    force_ref_ = std::max(force_ref_, 1e-12);
  }

  int size() const { return size_; }
  double forceReference() const { return force_ref_; }

  // The balance that residual component k scales, in words (error messages).
  std::string describe(Eigen::Index k) const {
    const auto tops = static_cast<Eigen::Index>(top_free_.size());
    if (k < tops) return std::string("the net force on the top along ") + "xyz"[top_free_[k]];
    if (bottomHeld(m_) && k >= size_ - 3)
      return std::string("the bottom end's position error along ") + "xyz"[k - (size_ - 3)];
    const int i = m_.first_dynamic + static_cast<int>((k - tops) / rotation_dofs_);
    return formatText("the moment about joint %d (s = %.4g m) of the riser below it", i, m_.segments[i].arc_start);
  }
  double tolerance() const { return tolerance_; }  // of the scaled residual's ∞-norm

  void pose(const Configuration& x, RiserPose& pose) {
    const Eigen::VectorXd y = restState(m_, x.orientation, x.top);
    poseFromState(m_, 0.0, y, pose);
  }

  // Scaled residual at load factor `lambda`.
  Eigen::VectorXd residual(const Configuration& x, double lambda) {
    RiserPose& p = ws_.pose;
    pose(x, p);
    computeLoads(m_, p, lambda, ws_.loads);
    const double lref = m_.length, mref = force_ref_ * lref;
    Eigen::VectorXd r(size_);
    Vec3 below = bottomHeld(m_) ? Vec3(-x.end_reaction) : Vec3::Zero();
    int k = static_cast<int>(top_free_.size());
    for (int i = m_.last_dynamic; i >= m_.first_dynamic; --i) {
      const Vec3 d = m_.segments[i].length * p.tangent(i);
      const Vec3 q = ws_.loads.moment[i] + d.cross(below);
      const int o = k + rotation_dofs_ * (i - m_.first_dynamic);
      if (m_.torsion) {
        r.segment<3>(o) = q / mref;
      } else {
        r[o] = q.dot(p.rotation[i].col(1)) / mref;
        r[o + 1] = q.dot(p.rotation[i].col(2)) / mref;
      }
      below += ws_.loads.force[i];
    }
    for (std::size_t c = 0; c < top_free_.size(); ++c) {
      const int axis = top_free_[c];
      const double known = knownTopForce(m_, axis, 0.0, x.top, Vec3::Zero(), lambda);
      r[c] = (below[axis] + known) / force_ref_;
    }
    if (bottomHeld(m_)) {
      Vec3 hold = m_.anchor;
      if (m_.bottom == BottomCondition::Clamped) hold -= m_.segments[m_.n].length * p.tangent(m_.n);
      const Vec3 end = m_.bottom == BottomCondition::Clamped ? p.position[m_.n] : p.end_position;
      r.tail<3>() = (end - hold) / lref;
    }
    return r;
  }

  // The bottom reaction enters the residual linearly; start Newton from its least-squares value for
  // the current shape (a zero initial reaction sends the first Newton steps far off for cables).
  void fitEndReaction(Configuration& x, double lambda) {
    if (!bottomHeld(m_)) return;
    const Eigen::VectorXd r0 = residual(x, lambda);
    const int rows = size_ - 3;
    Eigen::MatrixXd a(rows, 3);
    for (int k = 0; k < 3; ++k) {
      Configuration y = x;
      y.end_reaction[k] += force_ref_;
      a.col(k) = (residual(y, lambda) - r0).head(rows);
    }
    x.end_reaction += force_ref_ * a.colPivHouseholderQr().solve(-r0.head(rows));
  }

  // x ⊕ du: top coordinates, rotation increments (global rotation vector, or on the two normals), reaction.
  Configuration update(const Configuration& x, const Eigen::VectorXd& du) const {
    Configuration y = x;
    int k = 0;
    for (int c : top_free_) y.top[c] += du[k++] * m_.length;
    for (int i = m_.first_dynamic; i <= m_.last_dynamic; ++i) {
      Vec3 rot;
      if (m_.torsion) {
        rot = du.segment<3>(k);
      } else {
        const Mat3 r = x.orientation[i].toRotationMatrix();
        rot = du[k] * r.col(1) + du[k + 1] * r.col(2);
      }
      k += rotation_dofs_;
      const double angle = rot.norm();
      if (angle > 0) y.orientation[i] = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, rot / angle)) * x.orientation[i]).normalized();
    }
    if (bottomHeld(m_)) y.end_reaction += du.tail<3>() * force_ref_;
    return y;
  }

 private:
  RiserModel m_;
  RiserWorkspace ws_;
  std::vector<int> top_free_;
  int rotation_dofs_ = 3;
  int size_ = 0;
  double force_ref_ = 1.0;
  double tolerance_ = kTolerance;
};

// Newton with line search at one load level. Returns true when converged; x is updated in place.

bool newton(StaticProblem& problem, Configuration& x, double lambda, int& iterations, double& residual_norm,
            RunContext& context) {
  constexpr double kStep = 1e-7;        // forward-difference step of the scaled unknowns
  const int n = problem.size();
  problem.fitEndReaction(x, lambda);
  Eigen::VectorXd r = problem.residual(x, lambda);
  Eigen::MatrixXd jac(n, n);
  for (int it = 0; it < 100; ++it) {
    residual_norm = r.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(residual_norm)) return false;
    if (residual_norm < problem.tolerance()) return true;
    context.throwIfCancelled();
    ++iterations;
    for (int k = 0; k < n; ++k) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
      e[k] = kStep;
      jac.col(k) = (problem.residual(problem.update(x, e), lambda) - r) / kStep;
    }
    Eigen::VectorXd du = jac.partialPivLu().solve(-r);
    if (!du.allFinite() || (jac * du + r).norm() > 1e-6 * r.norm()) du = jac.completeOrthogonalDecomposition().solve(-r);
    // Limit rotations to 0.5 rad per iteration, then backtrack until the residual decreases.
    const double biggest = du.lpNorm<Eigen::Infinity>();
    if (biggest > 0.5) du *= 0.5 / biggest;
    const double merit = r.norm();
    bool accepted = false;
    double accepted_length = 0.0;
    for (double s = 1.0; s > 1e-3; s *= 0.5) {
      Configuration trial = problem.update(x, s * du);
      Eigen::VectorXd rt = problem.residual(trial, lambda);
      if (rt.allFinite() && rt.norm() < (1 - 1e-4 * s) * merit) {
        x = std::move(trial);
        r = std::move(rt);
        accepted = true;
        accepted_length = s;
        break;
      }
    }
    // A failed or heavily shortened Newton step (soft, nearly singular modes of slack cables): one
    // Levenberg–Marquardt iteration (core/least_squares.hpp) in the increments du from x, damping
    // (JᵀJ + μ·max diag(JᵀJ)·I) du = −Jᵀr with μ = 1e-10 … 1e5 rising tenfold until the residual falls.
    if (accepted_length < 0.25) {
      LeastSquaresProblem descent;
      descent.residuals = [&](const Eigen::VectorXd& du, Eigen::VectorXd& rt) {
        rt = du.isZero(0.0) ? r : problem.residual(problem.update(x, du), lambda);
        return true;
      };
      descent.jacobian = [&](const Eigen::VectorXd&, const Eigen::VectorXd&, Eigen::MatrixXd& j) {
        j = jac;
        return true;
      };
      LeastSquaresOptions options;
      options.max_iterations = 1;
      options.damping = LeastSquaresDamping::Levenberg;
      options.initial_damping = 1e-10;
      options.damping_increase = 10.0;
      options.max_damping = 5e5;  // the last μ tried is 1e5
      options.step_tolerance = 0.0;
      const LeastSquaresReport step = levenbergMarquardt(descent, Eigen::VectorXd::Zero(n), options);
      if (step.accepted_steps > 0) {
        x = problem.update(x, step.x);
        r = step.residuals;
        accepted = true;
      }
    }
    if (!accepted) {
      residual_norm = r.lpNorm<Eigen::Infinity>();
      return residual_norm < 1e3 * problem.tolerance();
    }
  }
  residual_norm = r.lpNorm<Eigen::Infinity>();
  return residual_norm < problem.tolerance();
}

// Configuration of joint state y: orientations of the dynamic segments, free top components; the rest from x.
Configuration configurationOf(const RiserModel& m, const Eigen::VectorXd& y, const Configuration& x) {
  Configuration out = x;
  for (int i = m.first_dynamic; i <= m.last_dynamic; ++i) {
    const Eigen::Index o = orientationStateOffset(m, i);
    out.orientation[i] = Eigen::Quaterniond(y[o], y[o + 1], y[o + 2], y[o + 3]).normalized();
  }
  for (int c = 0; c < 3; ++c)
    if (topForceKnown(m, c)) out.top[c] = y[c];
  return out;
}

// O(n) Newton at full load (no dense factorisation at run time). At rest the accelerations a(q) of
// the joint chart vanish exactly at equilibrium (the bottom row reads α²Φ = 0, so the bottom is held too;
// the model must be at rest, see atRest). Each iteration resets the chart to the current shape (θ = 0,
// ω = 0, where the neglected terms of the twin matrix vanish up to β'|a|) and solves (I − β'∂a/∂q) y = a with
// the O(n) joint Newton matrix (riser_joint_newton), Δq = β'y: pseudo-time stepping whose mass term I/β'
// regularises soft and singular directions (slack cables, spin without torsion).
// Damping by Deuflhard's natural monotonicity test, not by the residual norm: a chain started on a circular
// arc must pass through shapes of larger moment residual on its way to the catenary (measured: every
// backtracked step of the old residual test failed, down to β' = 1e-4 s²), while the simplified step
// Δq̄ = β'S⁻¹a(q + λΔq) (same factorisation, O(n)) shrinks. Accepted when |Δq̄| ≤ (1 − λ/10)|Δq|
// (Deuflhard uses λ/4; pseudo-time steps contract only by S⁻¹, 0.79 on case 5 at β' = 1 s²). β' grows ×10 after
// a full step, stays after a damped one, shrinks ×10 when no λ ≥ 1e-3 passes or the band LU is singular (then
// β' stays below that value). Converged 1e-3 below the dense path's tolerance; false (the caller then runs
// the dense Newton with load continuation) when β' falls below its floor or after 1000 iterations (O(n) each;
// the residual may grow on the way, so it is no measure of progress). A slack 3D cable held at both ends
// (30 m, n = 100, current at 45°) takes 142 damped iterations from its sagging arc, 1 s; a cap of 100 sent it
// to the dense path, which failed after 28 s.
bool bandedNewton(const RiserModel& model, StaticProblem& problem, Configuration& x, int& iterations,
                  double& residual_norm, RunContext& context, int max_iterations = 1000) {
  RiserModel m = model;
  m.formulation = Formulation::Joint;
  constexpr double kRate = 1.0;                    // [1/s] bottom Baumgarte rate: only α²Φ = 0 matters
  constexpr double kFirst = 1.0, kLargest = 1e8, kSmallest = 1e-4;  // [s²] pseudo-time β'
  constexpr double kRoundOffStep = 1e-12;  // [rad] a full step this small moves a 100 m riser's end by 1e-10 m
  OrientationChart chart(m, kRate);
  JointNewtonMatrix newton(m, chart, kRate);
  newton.useCoordinateSteps();
  Eigen::VectorXd y = restState(m, x.orientation, x.top), q, v, acc, res, step, simplified, trial_q, trial_y;
  problem.fitEndReaction(x, 1.0);
  Eigen::VectorXd r = problem.residual(x, 1.0);
  double dq = kFirst, ceiling = kLargest, previous_norm = std::numeric_limits<double>::infinity();
  double first_norm = 0.0, best_norm = 0.0;
  for (int it = 0; it < max_iterations; ++it) {
    residual_norm = r.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(residual_norm)) return false;
    // Below the dense path's tolerance by 1e-3: that path converges quadratically and ends far below it
    // (the cantilever stress test at PL²/EI = 1e-4 needs it), this one linearly at a fast rate.
    if (residual_norm < 1e-3 * problem.tolerance()) return true;
    // Or below the tolerance where a step no longer reduces the residual by a tenth: its round-off floor (a few
    // 1e-13 for a 100 m riser at n = 100, above the 1e-14 asked). Iterating there only moves the shape by
    // round-off, and how many such iterations ran (7 to 17 measured) depended on the last bit of every operation.
    if (residual_norm < problem.tolerance() && residual_norm > 0.9 * previous_norm) return true;
    previous_norm = residual_norm;
    // Progress: how far the smallest residual so far has come down from the first towards 1e-3 of the
    // tolerance, on a log scale (the residual itself may grow on the way).
    if (it == 0) first_norm = best_norm = residual_norm;
    best_norm = std::min(best_norm, residual_norm);
    const double target = 1e-3 * problem.tolerance();
    const double done = first_norm > target ? std::log(first_norm / best_norm) / std::log(first_norm / target) : 1.0;
    context.progress(0.05 + 0.9 * std::clamp(done, 0.0, 1.0), "statics: O(n) Newton");
    context.throwIfCancelled();
    ++iterations;
    chart.reset(y, q, v);
    v.setZero();
    acc.setZero(chart.size());
    chart.residual(0.0, q, v, acc, res);
    step = -res;
    if (!newton.solve({0.0, q, v, acc, 0.0, dq, true}, step) || !step.allFinite()) {
      // Numerically singular band LU: β' so large that the stiff (torsion) rows swamp the rest (n = 1000:
      // at β' = 1e4 s²). Lower β' and keep it below that from now on.
      ceiling = 0.1 * dq;
      dq = ceiling;
      if (dq < kSmallest) break;
      continue;
    }
    step *= dq;
    step.tail<kWorkIntegrals>().setZero();
    const double full = step.norm();
    // Rotations at most 0.5 rad per iteration (as the dense path): λ starts below 1 then.
    const double biggest = step.segment(3, step.size() - 3 - kWorkIntegrals).lpNorm<Eigen::Infinity>();
    const double first = biggest > 0.5 ? 0.5 / biggest : 1.0;
    double taken = 0.0;
    for (double lambda = first; lambda > 1e-3 && taken == 0.0; lambda *= 0.5) {
      trial_q = q + lambda * step;
      chart.residual(0.0, trial_q, v, acc, res);
      simplified = -res;
      if (!res.allFinite() || !newton.solve({0.0, q, v, acc, 0.0, dq, false}, simplified)) continue;
      simplified.tail<kWorkIntegrals>().setZero();
      if (!(dq * simplified.norm() <= (1 - lambda / 10) * full)) continue;
      chart.toState(trial_q, v, trial_y);
      normaliseState(m, trial_y);
      x = configurationOf(m, trial_y, x);
      problem.fitEndReaction(x, 1.0);
      r = problem.residual(x, 1.0);
      y = trial_y;
      taken = lambda;
    }
    // No λ passes the monotonicity test: at the round-off floor when the residual is below the tolerance, or below
    // ten times it while the full step itself is round-off (largest rotation < kRoundOffStep). The floor is not
    // n²ε exactly: measured on riser_default 2.0 n²ε at n = 200 (1.8e-11 against 1e-11 asked, full steps of
    // 1e-15 … 1e-14 rad) and 1.4 n²ε at n = 300; without this exit such a run shrank β' for 30 iterations, then
    // took dynamic relaxation. A large step at a small residual is not the floor but a soft direction (n = 1000
    // from its initial shape: residual 5.9e-10, step 1.6e-3 rad), which goes on iterating.
    if (taken == 0.0 && (residual_norm < problem.tolerance() ||
                         (residual_norm < 10 * problem.tolerance() && biggest < kRoundOffStep)))
      return true;
    dq = taken == 1.0 ? std::min(10 * dq, ceiling) : taken > 0.0 ? dq : 0.1 * dq;
    if (dq < kSmallest) break;
  }
  residual_norm = r.lpNorm<Eigen::Infinity>();
  return residual_norm < problem.tolerance();
}

// Gauss points (riser_loads) of the segments that are buoyant in water held at the still-water level within 1e-6 L
// (the damped motion pins them there within a millimetre on an 800 m riser: 47 of 51 such points after one
// period, the last 0.8 µm off). A point crossing the surface without being held is that close only by chance.
struct SurfaceHold {
  int points = 0;
  double first = 0.0, last = 0.0, lift = 0.0;  // [m] arc lengths, [N/m] largest buoyancy − weight
};

SurfaceHold buoyantPointsAtSurface(const RiserModel& m, const RiserPose& pose) {
  SurfaceHold hold;
  const double band = 1e-6 * m.length;
  for (int i = 0; i <= m.n; ++i) {
    const Segment& seg = m.segments[i];
    const double lift = seg.buoyancy_per_length - seg.weight_per_length;
    if (!(lift > 0)) continue;
    for (double x : kGaussX) {
      const double z = pose.position[i].z() + x * seg.length * pose.tangent(i).z();
      if (!(std::abs(z - m.water_level) <= band)) continue;
      const double s = seg.arc_start + x * seg.length;
      hold.first = hold.points == 0 ? s : std::min(hold.first, s);
      hold.last = hold.points == 0 ? s : std::max(hold.last, s);
      hold.lift = std::max(hold.lift, lift);
      ++hold.points;
    }
  }
  return hold;
}

// Dynamic relaxation (riser_relaxation) when the O(n) Newton fails from the initial shape: damped motion one
// pendulum period at a time, then the O(n) Newton from the shape reached once its scaled residual is below
// kHandOver (at most 100 iterations each try). Gives up after kPeriods periods or if the motion fails; stops with a
// SolverError after relaxationStepLimit steps (naming the residual component that did not settle, the mean step
// against the nominal one) and with FloatingRiserError when a buoyant part is held at the water line for half a
// period (an 800 m lazy-wave riser with its modules from the top: 10 871 steps in the first period instead of 40,
// then 55 000–62 000 per period, tens of minutes in all; now refused after 0.63 periods). The slack
// 3D cable held at both ends (n = 200, 1000) reaches a residual of 1e-8 in one period (11 s, 390-490 steps,
// most of them halved: Newton, not the step, sets their number) and Newton converges in 9-44 iterations.
bool relaxThenNewton(const RiserModel& m, StaticProblem& problem, Configuration& x, StaticSolution& out,
                     double& residual, RunContext& context) {
  constexpr int kPeriods = 30;
  constexpr double kHandOver = 1e-3;
  DampedRelaxation relax(m);
  relax.limitSteps(relaxationStepLimit(m));
  Eigen::VectorXd y = restState(relax.model(), x.orientation, x.top);
  RiserWorkspace ws = makeWorkspace(relax.model(), 0.0);
  // The floating test every eighth of a period (the first period alone took 5 956–10 871 steps at n = 20–40 on the
  // jump, and more at larger n), firing when four tests in a row (half a period: longer than a swing of the higher
  // modes, which the mass-proportional damper leaves underdamped, through the surface) see points held there.
  SurfaceHold hold;
  int held = 0;
  const auto floating = [&](const Eigen::VectorXd& state) {
    poseFromState(relax.model(), 0.0, state, ws.pose);
    hold = buoyantPointsAtSurface(m, ws.pose);
    held = hold.points > 0 ? held + 1 : 0;
    return held >= 4;
  };
  const auto floatingError = [&] {
    return FloatingRiserError(
        relax.time(), relax.steps(),
        formatText("the riser floats: its buoyant part (buoyancy above weight by up to %.4g N/m) is held at the "
                   "still-water level z = %.4g m between s = %.4g and %.4g m (%d load points) after %.3g s of dynamic "
                   "relaxation (%.3g pendulum periods, held for the last half). Buoyancy acts on the pipe's centre "
                   "line, all or nothing, so a pipe floating at the surface has no equilibrium in this model",
                   hold.lift, m.water_level, hold.first, hold.last, hold.points, relax.time(),
                   relax.time() / relax.period()),
        hold.first, hold.last, hold.lift);
  };
  for (int k = 0; k < kPeriods; ++k) {
    context.progress(0.05 + 0.9 * k / kPeriods, "statics: dynamic relaxation");
    try {
      // A period of a long chain can take minutes of damped motion: its progress is reported inside it too.
      relax.advance(
          y, relax.period(), context,
          [&](double f, const std::string&) {
            context.progress(0.05 + 0.9 * (k + f) / kPeriods, "statics: dynamic relaxation");
          },
          [&](double, const Eigen::VectorXd& state) { return floating(state); });
    } catch (const SolverError&) {
      return false;  // the motion itself failed: the dense path may still find the equilibrium
    }
    out.relaxation_time = relax.time();
    out.relaxation_steps = relax.steps();
    Configuration trial = configurationOf(relax.model(), y, x);
    problem.fitEndReaction(trial, 1.0);
    const Eigen::VectorXd shape = problem.residual(trial, 1.0);
    Eigen::Index worst = 0;
    const double shape_residual = shape.cwiseAbs().maxCoeff(&worst);
    if (relax.stopped() || (!relax.exhausted() && floating(y))) throw floatingError();
    if (relax.exhausted()) {
      // The floating test may not have seen half a period yet: say what the last one saw.
      const std::string surface =
          hold.points > 0 ? formatText("; its buoyant part was last seen held at the still-water level between s = "
                                       "%.4g and %.4g m: the riser may float, which this model cannot take (buoyancy "
                                       "acts on the pipe's centre line, all or nothing)",
                                       hold.first, hold.last)
                          : std::string();
      throw SolverError(
          "static equilibrium", relax.stalledTime(), relaxationStepLimit(m),
          formatText("dynamic relaxation did not settle within its limit of %ld steps (%.3g s of damped motion, "
                     "%.3g pendulum periods of %.3g s): its mean step in the period it stopped in fell to %.3g s "
                     "against the nominal %.3g s, and the scaled static residual at that period's start is %.3g "
                     "(largest in %s; Newton takes over below %.0e)%s. A load that jumps (contact with a very stiff "
                     "sea bed, buoyancy at the water line) or a shape far from equilibrium can cause this: start "
                     "nearer the equilibrium, or set initial.solve_statics = false to start from the initial shape "
                     "as it is",
                     relaxationStepLimit(m), relax.stalledTime(), relax.stalledTime() / relax.period(), relax.period(),
                     relax.stalledStep(), relax.nominalStep(), shape_residual, problem.describe(worst).c_str(),
                     kHandOver, surface.c_str()));
    }
    if (!(shape_residual < kHandOver)) continue;
    int iterations = 0;
    const bool ok = bandedNewton(m, problem, trial, iterations, residual, context, 100);
    out.iterations += iterations;
    if (ok) {
      x = std::move(trial);
      return true;
    }
  }
  return false;
}

// The fixed-height top on its axial spring (k = EA/L, 6.3e7 N/m for the peer riser): from the straight start the
// O(n) Newton stalls (6 iterations, β' down to its floor), as the spring's tension depends on the sag's shortening
// of the chain only to second order, which the linearisation at the straight shape cannot see. So the same riser is
// solved under a constant top tension T (the tensioner, whose statics the O(n) Newton solves), with T the root of
// the scalar mismatch g(T) = k (z_hang-off − z_top(T)) + W/2 − T (secant steps, each an O(n) solve warm-started
// from the last shape); at the root both models have the same equilibrium, which the O(n) Newton with the spring
// then confirms. False when any solve fails (the caller then relaxes).
bool axialSpringNewton(const RiserModel& m, StaticProblem& problem, Configuration& x, int& iterations,
                       double& residual_norm, RunContext& context) {
  RiserModel tensioned = m;
  tensioned.axial_stiffness = 0.0;
  tensioned.axial_weight_share = 0.0;
  tensioned.top = TopCondition::Tensioner;
  const double hang_off = m.topAt(0.0).position.z();
  const auto spring_tension = [&](const Configuration& c) {
    return m.axial_stiffness * (hang_off - c.top.z()) + m.axial_weight_share;
  };
  Configuration shape = x;
  const auto mismatch = [&](double tension, double& g) {
    tensioned.top_tension = tension;
    StaticProblem fixed_tension(tensioned);
    if (!bandedNewton(tensioned, fixed_tension, shape, iterations, residual_norm, context)) return false;
    g = spring_tension(shape) - tension;
    return true;
  };
  double t0 = spring_tension(x), g0 = 0.0;
  if (!mismatch(t0, g0)) return false;
  double t1 = t0 + g0, g1 = 0.0;
  if (!mismatch(t1, g1)) return false;
  for (int k = 0; k < 30 && std::abs(g1) > 1e-13 * std::abs(t1) && g1 != g0; ++k) {
    const double t2 = t1 - g1 * (t1 - t0) / (g1 - g0);
    t0 = t1;
    g0 = g1;
    t1 = t2;
    if (!mismatch(t1, g1)) return false;
  }
  if (!bandedNewton(m, problem, shape, iterations, residual_norm, context)) return false;
  x = std::move(shape);
  return true;
}

// The model held at its t = 0 top position with no top motion: a prescribed top acceleration at t = 0 (a
// clamped spline table, or harmonic motion without a ramp) would otherwise enter a(q) and no shape would
// have a(q) = 0 (riser_top_motion_table fell back to the dense path for this), and a top velocity the drag.
// Waves are left out as well: the static shape is the one in calm water.
RiserModel atRest(const RiserModel& model) {
  RiserModel m = model;
  m.top_mean = model.topAt(0.0).position;
  m.top_table = TopMotionSpline{};
  m.motion_amplitude.setZero();
  m.vessel = nullptr;
  m.sea = nullptr;  // calm water (the waves start from it with their ramp)
  return m;
}

}  // namespace

long relaxationStepLimit(const RiserModel& m) {
  constexpr double kSegmentSteps = 1e6;
  constexpr long kFewest = 2000;
  return std::max(kFewest, static_cast<long>(kSegmentSteps / (m.n + 1)));
}

StaticSolution solveStatics(const RiserModel& model, RunContext& context, StaticMethod method) {
  const RiserModel m = atRest(model);
  StaticProblem problem(m);
  Configuration x{m.initial_orientation, m.initial_top, Vec3::Zero()};
  StaticSolution out;
  double done = 0.0, increment = 1.0, residual = 0.0;
  // O(n) Newton first, then dynamic relaxation and the O(n) Newton from where it ends; the dense Newton with load
  // continuation only if both fail (from the initial shape again).
  if (method == StaticMethod::Automatic) {
    Configuration fast = x;
    bool found = m.axial_stiffness > 0 ? axialSpringNewton(m, problem, fast, out.iterations, residual, context)
                                       : bandedNewton(m, problem, fast, out.iterations, residual, context);
    if (!found) {
      const int tried = out.iterations;
      fast = x;
      found = relaxThenNewton(m, problem, fast, out, residual, context);
      if (found)
        context.warn(formatText("statics: the O(n) Newton did not converge from the initial shape (%d iterations); "
                              "equilibrium reached by dynamic relaxation (%.3g s of damped motion, %ld steps) "
                              "and the O(n) Newton from there",
                              tried, out.relaxation_time, out.relaxation_steps));
    }
    if (found) {
      x = std::move(fast);
      done = 1.0;
      out.load_steps = 1;
      out.banded = true;
    } else {
      // Say so: the fallback is O(n³) per iteration, minutes at n ≈ 1000.
      context.warn(formatText("statics: the O(n) Newton did not converge at full load, nor after %.3g s of dynamic "
                              "relaxation (%d iterations in all); used the dense Newton with load continuation, "
                              "O(n³) per iteration",
                              out.relaxation_time, out.iterations));
    }
  }
  while (done < 1.0) {
    const double lambda = std::min(1.0, done + increment);
    Configuration trial = x;
    context.progress(0.05 + 0.9 * done, "statics");
    if (newton(problem, trial, lambda, out.iterations, residual, context)) {
      x = std::move(trial);
      done = lambda;
      ++out.load_steps;
      increment *= 2;
    } else {
      increment *= 0.5;
      if (increment < 1.0 / 4096) {
        // Seen on a slack cable held at both ends (30 m, n = 100, before bandedNewton's cap was raised): from
        // the sagging arc this path stalled at load factor 0, 2.1e-11 against the tolerance, after 28 s.
        const std::string text = formatText(
                      "Newton's method found no equilibrium beyond load factor %.3g of gravity, buoyancy and current "
                      "(scaled residual %.3g, tolerance %.0e). Start from a shape nearer the equilibrium "
                      "(initial.inclination, initial.azimuth; a held bottom starts from an arc sagging to it), use "
                      "fewer segments (geometry.segment_count), or set initial.solve_statics = false to start from "
                      "that shape as it is",
                      done, residual, problem.tolerance());
        throw SolverError("static equilibrium", 0.0, out.iterations, text);
      }
    }
  }
  out.orientation = x.orientation;
  out.top = x.top;
  out.end_reaction = x.end_reaction;
  out.residual = residual;
  return out;
}

}  // namespace maris::riser
