// Helpers shared by the integrators' .cpp files (not part of the public API): option checks,
// the output-time schedule, interpolation, progress throttling and error-norm bookkeeping.
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "core/ode_types.hpp"
#include "core/run_context.hpp"

namespace maris::ode_detail {

// Throws std::invalid_argument (a programming error in the caller) for inconsistent options.
inline void checkOptions(const OdeOptions& o, const char* integrator, bool step_required) {
  auto fail = [&](const std::string& what) { throw std::invalid_argument(std::string(integrator) + ": " + what); };
  if (!std::isfinite(o.t0) || !std::isfinite(o.t1) || o.t1 < o.t0)
    fail("need finite t0 <= t1, got t0 = " + std::to_string(o.t0) + ", t1 = " + std::to_string(o.t1));
  if (step_required && !(o.step > 0.0 && std::isfinite(o.step)))
    fail("step must be positive and finite, got " + std::to_string(o.step));
  if (!(o.rtol >= 0.0) || !(o.atol >= 0.0) || o.rtol + o.atol <= 0.0)
    fail("need rtol >= 0, atol >= 0 and not both 0");
  if (!(o.min_step > 0.0) || !(o.max_step > 0.0)) fail("min_step and max_step must be positive");
  if (o.output_interval < 0.0) fail("output_interval must be >= 0");
  if (o.after_step && std::string(integrator) != "integrateRk4") fail("after_step is supported by integrateRk4 only");
}

inline std::string componentName(const OdeOptions& o, Eigen::Index i) {
  return o.state_name ? o.state_name(i) : "state component " + std::to_string(i);
}

// Output times t0 + k·interval strictly before t1 (t1 itself is always reported by the integrator).
class OutputSchedule {
 public:
  explicit OutputSchedule(const OdeOptions& o) : t0_(o.t0), t1_(o.t1), interval_(o.output_interval) {}
  bool everyStep() const { return interval_ <= 0.0; }
  // Next interior output time, or +inf when there is none left.
  double next() const {
    if (everyStep()) return INFINITY;
    const double t = t0_ + static_cast<double>(k_) * interval_;
    return t < t1_ - 1e-9 * interval_ ? t : INFINITY;
  }
  void advance() { ++k_; }

 private:
  double t0_, t1_, interval_;
  long k_ = 1;
};

// Cubic Hermite interpolant at t0 + θh from values and derivatives at both ends of a step of size h.
inline void hermiteCubic(double theta, double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& dy0,
                         const Eigen::VectorXd& y1, const Eigen::VectorXd& dy1, Eigen::VectorXd& out) {
  const double t2 = theta * theta, t3 = t2 * theta;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + theta, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  out = h00 * y0 + (h10 * h) * dy0 + h01 * y1 + (h11 * h) * dy1;
}

// Calls ctx.progress every 16 steps (the clock read in progress() is not free for cheap RHS).
class ProgressTicker {
 public:
  ProgressTicker(RunContext& ctx, const OdeOptions& o) : ctx_(ctx), t0_(o.t0), span_(o.t1 - o.t0) {}
  void tick(double t) {
    if ((++count_ & 15) == 0) ctx_.progress(span_ > 0 ? (t - t0_) / span_ : 1.0, "time integration");
  }
  void finish() { ctx_.progress(1.0, "time integration"); }

 private:
  RunContext& ctx_;
  double t0_, span_;
  long count_ = 0;
};

// One step's contribution to OdeStats::error_estimate: max|local error| / max(max|y|, atol).
inline double relativeLocalError(const Eigen::VectorXd& local_error, const Eigen::VectorXd& y, double atol) {
  if (local_error.size() == 0) return 0.0;
  const double scale = std::max(y.cwiseAbs().maxCoeff(), std::max(atol, 1e-300));
  return local_error.cwiseAbs().maxCoeff() / scale;
}

// Called when a step produced a non-finite value: throws SolverError naming the first component whose
// time derivative was non-finite in the stages (in evaluation order), else the first non-finite
// component of the new state (an overflow).
void throwNonFiniteStep(std::initializer_list<const Eigen::VectorXd*> stage_derivatives,
                        const Eigen::VectorXd& y_new, double t, long step, const OdeOptions& options);

}  // namespace maris::ode_detail
