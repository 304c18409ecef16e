// Stages of a seismic run, called by the scene (seismic_scene.cpp): input history, free-field report,
// finite-element runs and their post-processing.
#pragma once

#include <functional>
#include <vector>

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "core/work_estimate.hpp"
#include "seismic/free_field.hpp"
#include "seismic/seismic_parameters.hpp"

namespace maris::seismic {

// Incident displacement at the origin [m] as a function of time [s], leaving zero at `arrival` [s].
// Throws InputError for an unreadable accelerogram.
std::function<double(double)> incidentFunction(const SeismicParameters& p, double arrival);

// Incident displacement at the origin [m], sampled at t_k = k·dt (k < n), leaving zero at `arrival` [s].
// Throws InputError for an unreadable accelerogram.
std::vector<double> incidentHistory(const SeismicParameters& p, double dt, int n, double arrival);

// Time [s] at which the incident wave reaches the origin, chosen so that it reaches the model's
// first corner (bottom, upstream side) 0.05 s after t = 0.
double arrivalAtOrigin(const SeismicParameters& p, const FreeField& field);

// Free-field transfer functions, histories at the seabed (B) and water surface (A), energy check.
void addFreeFieldResults(const SeismicParameters& p, const FreeField& field, Results& results, RunContext& ctx);

// One finite-element run of the scene's model at one angle, with or without water.
struct FeCase {
  double angle_deg = 0.0;
  bool water = true;
  double element_size = 0.0, time_step = 0.0, stable_step = 0.0;  // [m], [s], [s]
  int cell_count = 0;
  long steps = 0;
  std::vector<double> station_x;                    // [m] stations along the reef flat (box: the seabed)
  std::vector<std::vector<double>> ux, uy;          // [m] station histories (t = n·dt)
  std::vector<double> incident;                     // [m] incident displacement at the origin, same times
  std::vector<double> probe_fe_uy, probe_ff_uy;     // [m] box only: water surface A, FE and free field
  std::vector<double> seabed_fe_ux, seabed_ff_ux, seabed_fe_uy, seabed_ff_uy;  // [m] box only: seabed B
  std::vector<std::vector<double>> snapshot_magnitude;  // [m] |u| per node per frame
  std::vector<double> snapshot_time;                // [s]
  int nx = 0, ny = 0;                               // grid cells (for the snapshots)
  double x0 = 0.0, y0 = 0.0;                        // [m] grid corner
};

class FeCaseHandOver;  // seismic_live.hpp

// Runs one case (throws SolverError, RunCancelled, InputError).
// `coarse_companion`: on the mesh about twice as coarse used for the discretisation-error estimate.
// `live`: hands copies of the records so far (and the current wave field) over for partial results.
FeCase runFeCase(const SeismicParameters& p, double angle_deg, bool water, bool snapshots, RunContext& ctx,
                 bool coarse_companion = false, FeCaseHandOver* live = nullptr);

// Peak ratios along the stations (paper eq 29): peak |u|, |v|, |a| over twice the incident peak (the
// surface of a homogeneous half-space under the same wave at vertical incidence); v and a by central
// differences of the histories.
struct PeakRatios {
  std::vector<double> ux, uy, vx, vy, ax, ay;  // [-] per station
};
PeakRatios amplificationRatios(const FeCase& c);

// Central-difference time derivative (one-sided at the ends): O(dt²) inside.
std::vector<double> timeRate(const std::vector<double>& u, double dt);
// Fourier amplitude |Σ a_k e^{-iωt_k} dt| on the n_fft grid (zero-padded), bins k = 0..n_fft/2.
std::vector<double> fourierAmplitude(const std::vector<double>& a, double dt, std::size_t n_fft);

// Acceleration spectral ratios H_a(x, f) = |A(x, f)|/(2|A_0(f)|) (paper eq 30) of every station, on the
// FFT bins f ≤ cutoff where the input spectrum exceeds band_fraction of its peak.
struct SpectralRatioMap {
  std::vector<double> frequency;           // [Hz] (n_f)
  std::vector<std::vector<double>> hx, hy; // [-] per station, per frequency
};
SpectralRatioMap spectralRatioMap(const FeCase& c, double cutoff_frequency, double band_fraction);
// Tables "spectral_ratio_map" (long format, heat-map data) and "spectral_ratio_lines" (H_a(f) at five
// points of the flat) with their plots.
void addSpectralMap(const SeismicParameters& p, const FeCase& c, Results& results);

// Pieces of the FE report that need only the records so far (shared by the final and the partial
// results): table "station_histories" (flat's edges and centre), the box's table "verification"
// (FE vs free field at B and A), each with its plot, and the wave-field frames of c's snapshots.
void addStationHistories(const FeCase& c, Results& results);
void addVerificationHistories(const FeCase& c, Results& results);
void addWaveFieldFrames(const SeismicParameters& p, const FeCase& c, Results& results);
// The frames draw every `i`-th column and `j`-th row of nodes of an nx × ny grid (≤ 160 × 80 cells).
struct FrameStride {
  int i = 1, j = 1;
};
FrameStride frameStride(int nx, int ny);

// Amplification, spectral ratios, histories, the water's effect, snapshots and the angle sweep.
void addFeResults(const SeismicParameters& p, const FeCase& main, const FeCase* dry, const std::vector<FeCase>& sweep,
                  Results& results);

// Discretisation-error estimate of the reef amplification: the relative change of the largest R_a
// (x and y) along the flat between the main mesh and a companion about twice as coarse. For a
// first-order error (the staircase flanks) this bounds the coarse mesh's error and over-estimates the
// main mesh's. Written to SolverStats and as scalars.
void addDiscretisationEstimate(const FeCase& main, const FeCase& coarse, Results& results);

// Lowest natural modes of the solid reef + seabed on the scene's mesh (modes.count, modes.base): a
// "modes" table and the global-mode scalars. Throws SolverError, RunCancelled.
void addModalResults(const SeismicParameters& p, Results& results, RunContext& ctx);

// The whole run: free field, then the finite-element model(s) and their post-processing.
Results solveSeismic(const SeismicParameters& p, RunContext& ctx);

// Its steps, cells, stored values, memory and output size from the main mesh, without solving.
WorkEstimate estimateSeismicWork(const SeismicParameters& p);

}  // namespace maris::seismic
