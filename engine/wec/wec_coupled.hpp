// Multi-body hydrodynamic coefficients: floats that interact through the water (radiation of one float's motion
// loads the others, and the diffraction field of each depends on all). Read from a multi-body BEM run (Nemoh /
// Capytaine Tecplot files with one body per float, wec_nemoh.hpp).
//
// Translational DoFs are numbered 2·float + (0 surge, 1 heave), as in wec_dynamics.hpp. A(ω), B(ω) are 2N×2N
// (symmetric for a passive BEM solution), X(ω) has 2N entries per unit wave amplitude in the scene's e^{+iωt}
// convention. The excitation is taken as computed by the BEM code with the bodies at their mesh positions, so
// it already carries each float's location phase: the floats' x positions in the scene must match the mesh
// (no e^{−ikx} factor is applied), and only waves along +x (heading 0) are available.
//
// Frequency domain with interaction (derived here, N floats; not in the paper): with T = blockdiag(T_1 … T_N),
// T_i = (−r_z0, r_x0)_i,
//   [ −ω² (diag I + Tᵀ A T) + iω (diag B_PTO + Tᵀ B T) + diag K_θ ] Θ = Tᵀ X,
//   Q = X + (ω² A − iω B) T Θ − ρ g A_w (T Θ)_z,   F_h,i = Q_i + ω² m_i (T Θ)_i.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/run_context.hpp"
#include "wec/wec_hydro.hpp"

namespace maris::wec {

struct WecModel;
struct FloatModel;
struct FrequencyResponse;

class CoupledHydro {
 public:
  struct Row {
    double omega = 0.0;            // [rad/s]
    Eigen::MatrixXd added_mass;    // [kg] 2N×2N
    Eigen::MatrixXd damping;       // [N·s/m] 2N×2N
    Eigen::VectorXcd excitation;   // [N/m] 2N, e^{+iωt}, location phase included
  };
  // rows sorted by ω (at least 2); a_inf [kg] 2N×2N.
  CoupledHydro(std::vector<Row> rows, Eigen::MatrixXd a_inf, std::string source);
  int dofs() const { return dofs_; }
  int bodies() const { return dofs_ / 2; }
  // PCHIP in ω per entry; ω = 0 anchor with A held and B = X = 0, end values beyond the table.
  double addedMass(int r, int c, double omega) const;
  double damping(int r, int c, double omega) const;
  Complex excitation(int r, double omega) const;
  const Eigen::MatrixXd& addedMassInfinity() const { return a_inf_; }
  double maxFrequency() const { return rows_.back().omega; }
  const std::vector<Row>& rows() const { return rows_; }
  const std::string& describe() const { return source_; }
  // The diagonal coefficients of float i as a single-body database (same interpolation).
  std::shared_ptr<const HydroDatabase> floatView(int i) const;

 private:
  std::vector<Row> rows_;
  Eigen::MatrixXd a_inf_;
  std::string source_;
  int dofs_ = 0;
  std::vector<MonotoneCubic> a_, b_, xr_, xi_;  // a_, b_ row-major 2N×2N
};

// Response of every float at ω with the interaction (formula above). Index i of the result is float i.
// pto_override ≥ 0 replaces the PTO damping of float `which` only. The per-float `inertia`, `damping` and
// `optimal_damping` use the diagonal terms (the optimum of one float with the others held at their own PTO is
// not that formula when the coupling is strong).
std::vector<FrequencyResponse> solveCoupledFrequency(const WecModel& model, double omega, int which = -1,
                                                     double pto_override = -1.0);

// Off-diagonal radiation channels of a coupled model (kernels, modal fits, A∞): entries whose damping or A∞
// exceeds 1e-6 of the largest diagonal one. Appends to model.cross.
void buildCrossRadiation(WecModel& model, double kernel_duration, double kernel_dt,
                         const RunContext* context = nullptr);

}  // namespace maris::wec
