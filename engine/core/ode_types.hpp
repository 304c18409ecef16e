// Types shared by every time integrator in core/ode.hpp: right-hand side, observer, options and
// statistics. See docs/numerics.md for which integrator to use when.
#pragma once

#include <functional>
#include <limits>
#include <string>

#include <Eigen/Core>

namespace maris {

// First-order system y' = F(t, y): writes F into `dydt` (already sized like y).
using OdeRhs = std::function<void(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt)>;

// Called at t0, at every output time (see OdeOptions::output_interval) and at t1, in increasing t.
using OdeObserver = std::function<void(double t, const Eigen::VectorXd& y)>;

struct OdeOptions {
  double t0 = 0.0;  // [s] start time
  double t1 = 1.0;  // [s] end time, > t0
  double step = 1e-3;  // [s] fixed step (RK4, generalized-α) or initial step (DOPRI5; <= 0: chosen automatically)
  double rtol = 1e-6;  // [-] relative tolerance: local error (DOPRI5) / Newton correction (generalized-α)
  double atol = 1e-9;  // [state units] absolute tolerance, same roles
  double min_step = 1e-14;  // [s] a step below this is a step-size collapse (SolverError)
  double max_step = std::numeric_limits<double>::infinity();  // [s] largest step DOPRI5 may take
  long max_steps = 50'000'000;  // more accepted steps than this is a SolverError
  double output_interval = 0.0;  // [s] observer spacing from t0; 0 = after every accepted step
  std::function<std::string(Eigen::Index)> state_name;  // names a state component in errors ("node 3 x")
  // integrateRk4 only (the others reject it): called after every step with the new state, which it may
  // change (project it back onto constraints, advance a stored history); the step's end slope, error
  // estimate and the observer then use the changed state. A non-finite state afterwards is a SolverError.
  std::function<void(double t, Eigen::VectorXd& y)> after_step;
};

struct OdeStats {
  long steps = 0;                 // accepted steps
  long rejected_steps = 0;        // steps rejected by error control or Newton failure
  long rhs_evaluations = 0;       // calls of the right-hand side (or residual)
  long jacobian_evaluations = 0;  // iteration-matrix (re)formations (implicit integrators)
  double error_estimate = 0.0;    // [-] sum over steps of the local error estimate's max norm divided by
                                  // max(|state|_max, atol): a rough relative global error bound (no
                                  // propagation factors), see docs/numerics.md for each integrator's estimator
  double last_step = 0.0;         // [s] size of the last full (not end-shortened) accepted step
};

}  // namespace maris
