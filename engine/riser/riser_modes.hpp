// Natural frequencies and mode shapes of the segment chain, linearised about a static equilibrium
// (the paper's "procedure of [60]"). Undamped (no spring dampers, no drag damping); the
// current's drag on the static shape is kept as a load; top held where its motion is prescribed.
//
// Why both formulations give the same frequencies: with Baumgarte feedback off, the absolute
// equations keep Φ̈ = 0, so Dᵀ(q) f(q) = 0 for every configuration q at rest; at an equilibrium
// (f = 0) this gives Dᵀ A = 0 for A = ∂f/∂q. The image of A therefore lies in the tangent space of
// the constraints, every eigenvector with ω ≠ 0 is a motion that keeps the chain connected, and on
// that space A is the joint-coordinate linearisation written in other coordinates (a similarity
// transform). The 3(n+2) constraint-violating directions only add zero eigenvalues, which are
// dropped. This needs f = 0 at the linearisation point, so the current's drag must stay in the model
// (dropping it leaves the bent shape unbalanced and the two linearisations differed by 7e-5).
// Test `AbsoluteAndJointLinearisationsGiveTheSameFrequencies` checks it numerically. When the loads do
// not depend on positions at all the A position columns vanish and both give the same matrix.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/results.hpp"
#include "riser/riser_statics.hpp"

namespace maris::riser {

struct RiserModes {
  std::vector<double> frequencies;           // [rad/s] ascending, constraint (zero) modes removed
  std::vector<std::vector<Vec3>> shapes;     // [-] node displacements (n+2 nodes) per mode, largest = 1
                                             //     (all zero for a pure torsion mode)
  std::vector<std::vector<double>> twists;   // [-] rotation of segment i about its own axis (n+1), largest = 1
  std::vector<double> torsion_share;         // [-] Σ twist² / Σ |rotation|² of the mode (1 = pure torsion)
  int unstable_count = 0;                    // [-] eigenvalues with Re λ > 1e-3 |λ| (flow past divergence, flutter)
  // Oscillatory eigenvalues with 1e-6 |λ| < Re λ ≤ 1e-3 |λ| (amplitude growth < 0.6 % per period): kept as
  // frequencies (Im λ). With internal flow on a coarse chain this is the discretisation's slight
  // non-conservativeness (curvature fit of eqs 47–49 with the Coriolis coupling), O(u³Δ³), docs/riser.md.
  int slowly_growing_count = 0;              // [-]
  double largest_growth_rate = 0.0;          // [1/s] largest Re λ > 0 of the kept (oscillatory) eigenvalues, also
                                             //       below 1e-6 |λ| (≈ 1e-14 |λ| round-off when conservative)
  double largest_growth_per_radian = 0.0;    // [-] its Re λ / |λ|
  double divergence_flow_speed = std::numeric_limits<double>::infinity();  // [m/s] |u| at which ω_1 → 0; ∞ without contents
};

// Linearises q̈ = f(q) about the static state by central differences of the O(n) accelerations
// (evaluateRhs with Baumgarte feedback off), A = ∂f/∂q, and solves the eigenproblem of -A: ω² are
// its positive real eigenvalues. Coordinates:
//   Joint:    free top coordinates + a rotation increment per dynamic segment (3, or 2 without torsion);
//   Absolute: position of each dynamic segment's origin (3) + the same rotation increments.
// Zero eigenvalues (directions violating a held end or, in A, a joint) are dropped. Dense O(N³) with
// N ≈ 3n (J) or 6n (A): meant for n up to a few hundred. Returns at most `count` modes.
// With internal flow (u ≠ 0) the Coriolis force −2 m_f l u ṫ makes the system gyroscopic, q̈ = A q + G q̇:
// then G = ∂(accelerations)/∂q̇ is differentiated too (drag off) and the first-order (state-space)
// eigenproblem of size 2N′ is solved on the N′ directions that keep the chain connected (null space of
// the constraint Jacobian, so no zero-eigenvalue Jordan blocks blur small frequencies). Frequencies are
// the imaginary parts of the eigenvalues on (|Re λ| ≤ 1e-6 |λ|) or slowly growing off (≤ 1e-3 |λ|, counted in
// slowly_growing_count) the imaginary axis; modes past divergence or in flutter are counted in unstable_count. Shapes: the real part of the complex mode at the phase that makes it most real.
RiserModes computeModes(const RiserModel& model, const StaticSolution& statics, int count,
                        Formulation linearisation = Formulation::Joint);

// The model the modes are computed for: no dampers, no top motion, no timed loads; `linearisation` its coordinates.
RiserModel modesModel(const RiserModel& model, Formulation linearisation);

// Appends the mode of frequency ω [rad/s] with eigenvector v to out (shape, twist, torsion share as computeModes).
// m is modesModel(…, Absolute); v in its coordinates: the three position components of every dynamic segment's
// origin divided by Δ (segment by segment), then every segment's rotation increments [rad] (about the three global
// axes with torsion, else about its two transverse axes at equilibrium). Used by the Krylov solver (riser_modes_krylov).
void appendAbsoluteMode(const RiserModel& m, const StaticSolution& statics, double omega, const Eigen::VectorXd& v,
                        RiserModes& out);

// Order of computeModes' dense eigenproblem (joint linearisation): 3 coordinates per dynamic segment (2 without
// torsion), doubled with internal flow (the state-space problem). Cannot be cancelled once started.
int modesEigenOrder(const RiserModel& model);
// Its wall time, estimated from the order (kModesSecondsPerOrderCubed, measured); front ends refuse a run whose
// uninterruptible stretch exceeds the work limit (core/work_estimate.hpp).
double modesSolveSeconds(const RiserModel& model);

// Flow speed |u| at which the lowest frequency reaches zero (divergence: the stiffness A(u) becomes
// singular; the Coriolis term cannot move an eigenvalue through zero). The flow's shape-dependent force
// is −m_f l u² k, so A(u) = A0 + u² A1 exactly at a fixed shape, and u_c² is the smallest positive
// eigenvalue of the pencil (−A0, A1) on the connected directions. Evaluated at the given static shape
// (exact for a straight riser; for a riser bent by current the shape itself changes with u). Returns
// +∞ without contents (m_f = 0) or when no positive u² exists (joint coordinates).
double divergenceFlowSpeed(const RiserModel& model, const StaticSolution& statics);

// Warning text for slowly growing modes: "2 linearised modes grow slowly (largest Re λ = 3.9e-06 1/s,
// 4.5e-06 per radian, e-folding time 2.5e+05 s): …artefact… (docs/riser.md)".
std::string slowGrowthNote(int count, double growth_rate, double growth_per_radian);

// Animation of the modes for the 3D view: for each mode, `frames_per_mode` frames over one period,
// the static shape plus amplitude·sin(phase)·shape, amplitude = 5 % of L (torsion modes: the tube
// colour shows the twist). Frame time = mode index (from 0) + phase/(2π), so mode k plays on [k, k+1).
// Shapes are coloured by the modal displacement magnitude (twist for torsion-dominated modes).
void appendModeFrames(const RiserModel& model, const StaticSolution& statics, const RiserModes& modes,
                      int frames_per_mode, View3D& view);

}  // namespace maris::riser
