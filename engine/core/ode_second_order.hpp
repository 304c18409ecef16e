// Implicit generalized-α integrator for (stiff) second-order systems
//     M(t, q) q'' = f(t, q, q')
// in the form of Arnold & Brüls (2007, "Convergence of the generalized-α scheme for constrained
// mechanical systems", Multibody Syst. Dyn. 18:185–202), with the parameters of Chung & Hulbert (1993,
// J. Appl. Mech. 60:371–375) from the spectral radius at infinite frequency ρ∞ ∈ [0, 1]:
//     α_m = (2ρ∞ − 1)/(ρ∞ + 1),  α_f = ρ∞/(ρ∞ + 1),  γ = 1/2 + α_f − α_m,  β = (γ + 1/2)²/4.
// Per step (h), with the true acceleration q̈ satisfying the equation at t_{n+1} and a pseudo-acceleration a:
//     M(t_{n+1}, q_{n+1}) q̈_{n+1} = f(t_{n+1}, q_{n+1}, v_{n+1})
//     (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) q̈_{n+1} + α_f q̈_n,          a_0 = q̈_0
//     q_{n+1} = q_n + h v_n + h² (1/2 − β) a_n + h² β a_{n+1}
//     v_{n+1} = v_n + h (1 − γ) a_n + h γ a_{n+1}
// Second-order accurate, unconditionally stable for linear problems; ρ∞ = 1 is the trapezoidal rule
// (no numerical damping, energy of a linear undamped system conserved), smaller ρ∞ damps the
// high-frequency (unresolved) modes, ρ∞ = 0 annihilates them in one step.
// The unknown q̈_{n+1} is found by Newton's method on r = M q̈ − f; its Jacobian along the step is
//     S = ∂r/∂q̈ + γ' ∂r/∂v + β' ∂r/∂q,   γ' = γ h (1−α_f)/(1−α_m),  β' = β h² (1−α_f)/(1−α_m)
//       = M + γ' C_t + β' K_t   (tangent damping and stiffness).
#pragma once

#include <functional>

#include <Eigen/Core>

#include "core/ode_types.hpp"
#include "core/run_context.hpp"

namespace maris {

struct GeneralizedAlphaCoefficients {
  double alpha_m = 0.0, alpha_f = 0.0, gamma = 0.5, beta = 0.25;
};
// The Chung–Hulbert coefficients above; throws std::invalid_argument if rho_inf is outside [0, 1].
GeneralizedAlphaCoefficients generalizedAlphaCoefficients(double rho_inf);

// What solve_iteration_matrix is asked to do: solve S x = b at the state below.
struct IterationMatrixRequest {
  double t;                // [s] time of the state
  const Eigen::VectorXd& q;    // current Newton iterate of the coordinates
  const Eigen::VectorXd& v;    // ... of the velocities
  const Eigen::VectorXd& acc;  // ... of the accelerations q̈
  double dv_dacc;          // [s]  γ' above (0 when solving for the initial acceleration: S = M)
  double dq_dacc;          // [s²] β' above (0 likewise)
  bool refresh;            // true: form/factorise S at this state; false: the last S may be reused
};

struct SecondOrderSystem {
  Eigen::Index size = 0;  // number of coordinates n; q, v, q̈ and the residual all have this size

  // Required. Writes r = M(t, q)·acc − f(t, q, v) into `residual` (sized n). The integrator drives r to 0.
  std::function<void(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& acc,
                     Eigen::VectorXd& residual)>
      residual;

  // Optional. Overwrites `rhs` (sized n) with the solution x of S x = rhs, S as in the file comment, for
  // systems with structure (banded, block-tridiagonal). Return false if S is singular (a Newton failure).
  // Default: dense S by forward differences of `residual` (n extra calls) and a partial-pivoting LU.
  std::function<bool(const IterationMatrixRequest& request, Eigen::VectorXd& rhs)> solve_iteration_matrix;

  // Optional. Called after every accepted step with the new coordinates and velocities, which it may change
  // (projection onto a constraint manifold, renormalisation). The accelerations are kept as they are, so a
  // projection should be small (of the order of the step's truncation error).
  std::function<void(double t, Eigen::VectorXd& q, Eigen::VectorXd& v)> project_step;

  // Optional, for the default path: S is banded, S_ij = 0 unless −lower ≤ j − i ≤ upper (a chain whose
  // coordinate i couples to i ± b: b and b). Then S is formed from lower + upper + 1 grouped residual
  // differences instead of n and factorised by BandedLu in O(n·b²). −1 (either): dense.
  Eigen::Index lower_bandwidth = -1, upper_bandwidth = -1;

  // Optional: the last `passive_coordinates` coordinates feed back into no other (their values never enter
  // another row of the residual: work or energy integrals kept for the record). The Newton convergence test
  // leaves them out, so an iteration matrix that gives them the identity (their corrections then follow the
  // others' one iteration behind) does not fail or prolong a step for their sake; they converge with the rest.
  Eigen::Index passive_coordinates = 0;
};

// Sees t0, every output time and t1: coordinates, velocities and accelerations (q̈). Between step
// points q and v are cubic Hermite interpolants (q, v, q̈ at both ends), q̈ is linear.
using SecondOrderObserver = std::function<void(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                               const Eigen::VectorXd& acc)>;

struct GeneralizedAlphaOptions {
  double rho_inf = 0.8;            // [-] spectral radius at infinite frequency, in [0, 1]
  int max_newton_iterations = 10;  // per attempt of a step
  bool halve_on_failure = true;    // on Newton failure retry with h/2 (not below OdeOptions::min_step); after
                                   // 4 good steps the step doubles again, up to OdeOptions::step
  int startup_halvings = 0;        // first step h/2^m, doubling every step up to h: resolves an initial
                                   // layer (see below); ≈ log2(h / fastest time constant) when needed
};
// Initial layer: when the initial state excites modes far faster than h (q̈0 dominated by them, e.g.
// v0 = 0 on a heavily damped mode), the terms h²(1/2 − β) a_0 and h(1 − γ) a_0 carry that acceleration
// into the slow solution as an O(1) error that does not decay for ρ∞ < 1 (x'' + 100001 x' + 1e5 x = 0,
// x0 = 1, v0 = 0, h = 0.01: slow-mode amplitude wrong by +3 % at ρ∞ = 0.8, +28 % at 0.5, +250 % at 0).
// Start from a consistent state (statics) or set startup_halvings (10 there gives 1e-5).

// The integrator's accelerations at the end of a call, to continue in a later call as one call would have
// gone on. Without it each call starts from the exact q̈0 of its initial state with a_0 = q̈0: where modes far
// faster than h are present but unresolved (damped by ρ∞ over many steps, as in a finely discretised riser),
// that restart injects their full acceleration, and the next step's Newton iteration starts far off
// (riser case 5 in absolute coordinates at n = 400, h = 50 ms, restarted every 0.5 s: 359 of 1623 steps
// rejected; 44 of 833 when restarted every 6 s).
struct GeneralizedAlphaState {
  Eigen::VectorXd acceleration;         // q̈_n
  Eigen::VectorXd pseudo_acceleration;  // a_n
};

// Integrates from (q, v) at options.t0 to options.t1 in equal nominal steps no longer than options.step (the
// fewest that fit); q and v hold the end state on return. With `state`: if both its vectors have
// size n they are the starting q̈_0 and a_0 (no initial solve); on return it holds the end's q̈ and a.
// Uses from OdeOptions: t0, t1, step, min_step, max_steps, output_interval, state_name (names coordinate i),
// and rtol/atol for Newton convergence: stop when the corrections of q and of v have weighted RMS
// ≤ 1 with weights 1/(atol + rtol·|value|) (or when the contraction-rate estimate says so).
// The iteration matrix is kept across steps and refreshed when the step changes or Newton converges slowly, and
// formed once more at the second iterate if that diverges from a matrix just formed at the predictor.
// Error estimate per step: h² |β − 1/6| |q̈_{n+1} − q̈_n| (Newmark family's displacement truncation term).
// Throws SolverError naming the coordinate with the largest Newton correction when Newton fails at the
// smallest allowed step, or the non-finite component; RunCancelled; std::invalid_argument for bad options.
OdeStats integrateGeneralizedAlpha(const SecondOrderSystem& system, Eigen::VectorXd& q, Eigen::VectorXd& v,
                                   const OdeOptions& options, const GeneralizedAlphaOptions& alpha_options,
                                   RunContext& ctx, const SecondOrderObserver& observer = {},
                                   GeneralizedAlphaState* state = nullptr);

}  // namespace maris
