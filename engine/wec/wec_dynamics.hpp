// Equations of motion of the hinged floats, shared by the time integrators (RK4 in wec_time.cpp, the paper's
// Newmark two-loop scheme in wec_newmark.cpp). Internal to the wec scene.
//
// State layout (written by initialState, read by rhs):
//   classical  per float: [θ, θ̇]                       (2 states)
//   augmented  per float: [x, z, θ, ẋ, ż, θ̇]           (6 states)
//   then, state-space memory only, the modal states of every radiation channel (fit.order each).
// Translational DoFs are numbered 2·float + (0 surge, 1 heave). A radiation channel is one entry (row, col) of
// the radiation matrix: the force on DoF `row` from the velocity of DoF `col`; the diagonal channels come from
// FloatModel::surge/heave, off-diagonal ones (multi-body coefficients) from WecModel::cross.
//
// Classical (paper eqs 8–11 generalised to coupled A∞): with T_i = (−r_z, r_x)_i and c_i = −r_i θ̇_i² the
// centripetal acceleration of float i,
//   Σ_j (δ_ij I_i + T_iᵀ A∞_ij T_j) θ̈_j = T_iᵀ (F_exc,i − μ_i − F_hs,i − Σ_j A∞_ij c_j) + M_PTO,i.
// Augmented (paper eqs 18–30): M q̈ + C_qᵀ λ = Q, C_q q̈ = Q_c − 2αĊ − α²C, M = blockdiag(m, m, I_cg) + A∞ on
// (x, z) (constant, inverted once); λ from the Schur complement C_q M⁻¹ C_qᵀ; λ is the hinge reaction.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "wec/wec_model.hpp"
#include "wec/wec_time.hpp"

namespace maris::wec {

// Loads and energies of one float at one instant (diagnostics for the histories).
struct FloatLoads {
  double theta = 0, theta_dt = 0, theta_dtdt = 0, fx = 0, fz = 0, moment = 0;
  double p_pto = 0, p_exc = 0, p_rad = 0, energy = 0;
};

// One radiation channel: its memory force μ = ∫K(τ) v_col(t − τ) dτ acts on DoF `row`.
struct MemoryChannel {
  int row = 0, col = 0;
  const ModalKernel* fit = nullptr;
  int offset = 0;                      // first modal state (state-space only)
  DirectConvolution convolution;       // direct only, kernel sampled at the time step
  double mu_prev = 0.0, mu_now = 0.0;  // [N] direct memory at t_{n−1}, t_n
  // μ from the modal states (state-space) or extrapolated linearly to frac of the step (direct).
  double memory(const Eigen::VectorXd& y, bool state_space, double frac) const;
  // ẇ = p w + v for every mode.
  void derivative(const Eigen::VectorXd& y, double v, Eigen::VectorXd& dy) const;
};

struct FloatSystem {
  const FloatModel* f = nullptr;
  ExcitationSeries excitation;
  int offset = 0;  // first state of this float
};

class WecDynamics {
 public:
  WecDynamics(const WecModel& model, const IncidentWaves& waves, const TimeDomainOptions& options);

  int size() const { return size_; }
  Eigen::VectorXd initialState() const;
  // dy = f(t, y); frac ∈ [0, 1] is the position inside the current step (direct memory extrapolation).
  // loads (size = floats) is filled when given.
  void rhs(double t, double frac, const Eigen::VectorXd& y, Eigen::VectorXd& dy, std::vector<FloatLoads>* loads);
  // Augmented: measures |C|, |C_q q̇| and (if options.projection) projects (x, z, ẋ, ż) onto the constraints.
  void project(Eigen::VectorXd& y, double& drift_p, double& drift_v) const;
  // Direct convolution: append the velocities of the completed step.
  void advanceHistory(const Eigen::VectorXd& y);
  // Translational velocities of every DoF (2·floats) at state y.
  void velocities(const Eigen::VectorXd& y, Eigen::VectorXd& v) const;

  long evaluations() const { return evaluations_; }
  const std::vector<FloatSystem>& floats() const { return systems_; }
  const std::vector<MemoryChannel>& channels() const { return channels_; }
  const TimeDomainOptions& options() const { return o_; }

 private:
  void classical(double t, double ramp, const Eigen::VectorXd& y, Eigen::VectorXd& dy, std::vector<FloatLoads>* loads);
  void augmented(double t, double ramp, const Eigen::VectorXd& y, Eigen::VectorXd& dy, std::vector<FloatLoads>* loads);

  const WecModel& model_;
  const IncidentWaves& waves_;
  TimeDomainOptions o_;
  std::vector<FloatSystem> systems_;
  std::vector<MemoryChannel> channels_;
  Eigen::MatrixXd a_inf_;  // [kg] 2N×2N A∞ (diagonal without multi-body coefficients)
  Eigen::MatrixXd m_inv_;  // augmented: inverse of the constant 3N×3N mass matrix
  int size_ = 0;
  long evaluations_ = 0;
  // Workspace (sized once).
  Eigen::VectorXd vel_, mu_, exc_, rhs_n_, acc_, q_, lam_;
  Eigen::MatrixXd mat_n_, cq_;
  std::vector<double> rx_, rz_;
};

// Appends the loads of each recorded instant to the histories and integrates the PTO energy, excitation and
// radiation works by the trapezoid rule between consecutive steps.
class HistoryRecorder {
 public:
  HistoryRecorder(TimeDomainResult& r, std::size_t floats);
  // Call once per step with the loads at t_n; h = t_n − t_{n−1} (0 at the first instant).
  void accumulate(const std::vector<FloatLoads>& loads, double h);
  void record(double t, double eta, const std::vector<FloatLoads>& loads);

 private:
  TimeDomainResult& r_;
  std::vector<double> e_pto_, w_exc_, w_rad_;
  std::vector<FloatLoads> prev_;
};

// Augmented formulation integrated with the paper's two-loop scheme (wec_newmark.cpp): explicit Newmark
// (β = 0, γ = ½) on θ, Newton–Raphson on the position constraints for (x, z), velocities from C_q q̇ = 0,
// accelerations and multipliers from the KKT system; the implicit velocity update is iterated to convergence.
TimeDomainResult simulateNewmark(const WecModel& model, const IncidentWaves& waves, const TimeDomainOptions& options,
                                 RunContext* context, const TimeDomainObserver& observe = {});
// Stability limit of the explicit Newmark (central-difference) scheme: h ω_max ≤ 2, ω_max the highest undamped
// pitch frequency [s].
double newmarkStabilityStep(const WecModel& model);

}  // namespace maris::wec
