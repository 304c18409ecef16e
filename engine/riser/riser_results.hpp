// Turns states of a riser run into Results: history table (probe points, end reactions, energies,
// work, energy balance, constraint drift), profiles along the riser (positions, tension, bending
// and torsional stress, curvature) at chosen times, node positions of every frame, View3D frames
// (riser as a tube coloured by bending stress), plots and key scalars.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_fatigue.hpp"
#include "riser/riser_modes.hpp"
#include "riser/riser_parameters.hpp"
#include "riser/riser_statics.hpp"

namespace maris::riser {

// Quantities along the riser at one instant, per joint j = 1..n (index 0 = top end, n+1 = bottom end).
struct RiserProfile {
  std::vector<double> arc_length;       // [m] s of node k
  std::vector<Vec3> position;           // [m] node k
  std::vector<double> tension;          // [N] -F_k · t_k (node k, reaction of the joint; ends from supports)
  std::vector<double> bending_stress;   // [Pa] σ_b = √(M'_2² + M'_3²)/w_B (0 at the ends)
  std::vector<double> stress_xy;        // [Pa] σ_xy = M'_3/w_B (bending about the segment's z' axis)
  std::vector<double> stress_xz;        // [Pa] σ_xz = M'_2/w_B (bending about y')
  std::vector<double> torsional_stress; // [Pa] σ_t = M'_1/w_T
  std::vector<double> curvature;        // [1/m] bend angle / Δ
};

// Evaluates the profile of state y at time t (runs one right-hand side evaluation in `ws`).
RiserProfile evaluateProfile(const RiserModel& m, RiserWorkspace& ws, double t, const Eigen::VectorXd& y);

class RiserRecorder {
 public:
  // Reactions, tension and stresses are those of the ideal constraints at the sampled state: the
  // recorder evaluates without the Baumgarte term 2αΦ̇ + α²Φ of the run. That term is an artificial
  // correction force; while RK4's α followed the step (0.1/h) it did not vanish as h → 0, and it kept the
  // J and A top reactions ~3e-8·T apart at any step (measured on the JointAndAbsolute test case).
  RiserRecorder(const RiserModel& model, const RiserParameters& parameters);

  // Records state y at time t: a history row (or, with `history` false, only the joint stresses for fatigue);
  // optionally a 3D frame and a profile table.
  void sample(double t, const Eigen::VectorXd& y, bool frame, const std::optional<std::string>& profile_name,
              bool history = true);
  // Publish partial results to `context` while recording (for live plots): at the context's throttled
  // rate, a copy of the history so far with its plots and the latest 3D frame. nullptr turns it off.
  void publishPartialsTo(RunContext* context) { live_ = context; }
  // Natural frequencies and mode shapes about the static state: tables "modes" and "mode_shapes".
  void addModes(const RiserModes& modes);
  // Results with everything recorded, the summary of the static solution the run started from and the solver
  // statistics.
  Results finish(const SolverStats& stats, const StaticSolution& statics);

 private:
  // Appends the joint stresses of the profile just filled to the fatigue series (fatigue.enabled).
  void recordFatigueSample(double t);
  const RiserModel& m_;
  const RiserParameters& p_;
  RiserWorkspace ws_;
  // Buffers of sample(), reused from sample to sample (a run records thousands).
  Eigen::VectorXd dy_;
  RiserProfile profile_;
  std::vector<double> row_, extra_;
  Results r_;
  Table history_, nodes_;
  std::vector<Vec3> initial_nodes_;
  // One per row of output.probes: history columns probe_dx.. (first), probe2_dx.., ...
  struct Probe {
    double arc_length = 0.0;   // [m]
    // Stresses are interpolated linearly in arc length between joints `joint_above` and the one below it (weight
    // `weight_below` on the lower one; 0 beyond the end joints): O(Δ²) at s, where the nearest joint, up to Δ/2
    // away, was O(Δ) (σ_b(L/2) of case 5 converged at first order in n).
    int joint_above = 1;
    double weight_below = 0.0;  // [-]
    Vec3 start = Vec3::Zero(); // [m] position at the first sample
    double max_displacement = 0.0, max_bending = 0.0;  // [m], [Pa] over the samples so far
  };
  std::vector<Probe> probes_;
  Vec3 pose_end_ = Vec3::Zero();
  double energy0_ = 0.0, energy_scale_ = 0.0, balance_max_ = 0.0, drift_max_ = 0.0;
  double max_bending_ = 0.0, max_torsion_ = 0.0, max_tension_ = 0.0;
  bool first_ = true;
  RunContext* live_ = nullptr;
  std::vector<double> fatigue_time_;             // [s] samples kept for fatigue (fatigue.enabled)
  std::vector<JointStressSeries> fatigue_;       // joints 1..n
  SeabedRecorder seabed_;                        // touchdown and contact force (model with a sea bed)

  std::shared_ptr<const Results> partialResults() const;
  void addHistoryPlots(Results& out) const;
  void addProbeScalars(Results& out) const;
};

// Warnings for a finished run whose own accuracy measures say it cannot be trusted although no step failed:
// the energy balance off by more than 5 % of the run's energy scale, or the integrator's error estimate above
// 0.1 (relative). Seen: DOPRI5 at rtol 1e-3 on the 3D cable (A3, n = 100) ran 197 723 steps on its stability
// limit and ended with the balance off by 100 % and an estimate of 171, without a word.
std::vector<std::string> accuracyWarnings(const Results& results);

}  // namespace maris::riser
