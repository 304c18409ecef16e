// Time integrators shared by every scene (docs/numerics.md has orders, stability and measured numbers):
//   integrateRk4               explicit, fixed step, order 4           (ode_rk4.cpp)
//   integrateDopri5            explicit, adaptive, order 5(4), dense    (ode_dopri5.cpp)
//   integrateGeneralizedAlpha  implicit, second-order systems M q'' = f (ode_second_order.hpp)
//
// Common behaviour of all of them:
//   - the state is integrated in place: `y` holds y(t0) on entry and y(t1) on return;
//   - the observer sees t0, every output time and t1 (outputs between step points are interpolated);
//   - ctx.throwIfCancelled() every step (RunCancelled), ctx.progress(fraction, "time integration");
//   - a non-finite state after an accepted step throws SolverError naming the component
//     (OdeOptions::state_name), as does a step size below min_step or more than max_steps steps.
#pragma once

#include "core/ode_second_order.hpp"
#include "core/ode_types.hpp"
#include "core/run_context.hpp"

namespace maris {

// Classical 4th-order Runge–Kutta with fixed step options.step; the last step is shortened to end
// exactly at t1 (step points are t0 + k·step, not accumulated sums).
// Outputs between step points use the step's cubic Hermite interpolant (y and y' at both ends,
// error O(h^4), the same order as the method), so the step size is never changed for output.
// Error estimate: the FSAL-embedded 3rd-order solution b̂ = (1/6, 1/3, 1/3, 0, 1/6) using
// k5 = F(t+h, y_{n+1}) (which is the next step's k1, so it costs nothing): local error ≈ h (k4 − k5)/6.
// It measures the 3rd-order companion, so it over-estimates RK4's own error (by O(1/h)).
// RHS evaluations: 4 per step + 1. OdeOptions::after_step (if set) may change the state after each step.
// Throws SolverError (non-finite state, bad options), RunCancelled.
OdeStats integrateRk4(const OdeRhs& rhs, Eigen::VectorXd& y, const OdeOptions& options, RunContext& ctx,
                      const OdeObserver& observer = {});

// Dormand–Prince 5(4) (Dormand & Prince 1980; Hairer, Nørsett & Wanner, Solving ODEs I, §II.5):
// 7 stages with FSAL (6 RHS evaluations per step), local extrapolation (the 5th-order solution is kept),
// error norm = RMS_i(e_i / (atol + rtol·max(|y_i(t)|, |y_i(t+h)|))), step accepted when ≤ 1,
// PI step-size control h_new = h·0.9·err^−0.17·err_prev^0.04, factor clipped to [0.2, 10]
// (no increase right after a rejection), h ≤ max_step. A non-finite error estimate rejects the step.
// Observer outputs use the standard 4th-order continuous extension (Hairer et al. §II.6).
// options.step ≤ 0 picks the initial step from the RHS scale (Hairer's starting-step heuristic).
// Throws SolverError on step-size collapse (names the component with the largest error), on a
// non-finite state, or past max_steps; RunCancelled.
OdeStats integrateDopri5(const OdeRhs& rhs, Eigen::VectorXd& y, const OdeOptions& options, RunContext& ctx,
                         const OdeObserver& observer = {});

}  // namespace maris
