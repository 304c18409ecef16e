// Post-processing of oscillation records, from the model or imported from CFD or a tank test:
// amplitude from peaks, amplitude spectra of y and lift with the paper's lift-alternation count
// n = round(f2/f1) (eq 22), converted power ⟨cẏ²⟩ (eq 13), ⟨F ẏ⟩ (eq 8) and efficiency (eqs 14–15).
#pragma once

#include <string>
#include <vector>

namespace maris::fiv {

// Spectra of a uniformly sampled record and their peaks.
struct SpectralPeaks {
  std::vector<double> frequency;               // [Hz] one-sided bins k/(N dt)
  std::vector<double> displacement_amplitude;  // [m] amplitude of y per bin (mean removed)
  std::vector<double> lift_amplitude;          // [N] amplitude of the lift per bin (empty lift: zeros)
  double f1 = 0.0;           // [Hz] main peak of the y spectrum (parabolic refinement between bins)
  double f2 = 0.0;           // [Hz] largest local peak of the lift spectrum above 1.5 f1; 0 if none
  double alternations = 0;   // [-] n = round(f2/f1) (paper eq 22); 0 if no f2
};

// Throws std::invalid_argument for fewer than 8 samples or dt <= 0.
SpectralPeaks analyseSpectra(const std::vector<double>& displacement, const std::vector<double>& lift, double dt);

// An imported record. ydot and lift may be empty (ydot is then differentiated from y).
struct ImportedSeries {
  std::vector<double> time;  // [s] increasing
  std::vector<double> y;     // [m]
  std::vector<double> ydot;  // [m/s]
  std::vector<double> lift;  // [N] transverse fluid force
};

// Reads a CSV with columns time, y and optionally ydot, lift (names row, optional units row,
// '#' comments). Non-uniform sampling is resampled linearly onto the mean step. Throws InputError.
ImportedSeries readSeriesCsv(const std::string& path);
ImportedSeries parseSeriesCsv(const std::string& text, const std::string& origin);

struct SeriesAnalysis {
  double amplitude = 0.0;         // [m] mean half peak-to-peak over whole cycles
  double amplitude_spread = 0.0;  // [m] standard deviation of the per-cycle amplitudes
  int cycles = 0;                 // whole cycles (zero up-crossings of y − mean)
  double frequency = 0.0;         // [Hz] from the up-crossings
  SpectralPeaks spectra;          // f1, f2, n
  double power_damper = 0.0;      // [W] c⟨ẏ²⟩ over the whole cycles
  double power_fluid = 0.0;       // [W] ⟨lift·ẏ⟩ over the whole cycles (0 without lift)
  double fluid_power = 0.0;       // [W] ½ρU³L(D + 2A)
  double efficiency = 0.0;        // [-] P / (P_fluid · 16/27)
};

// Half peak-to-peak of y per whole cycle (between zero up-crossings of y − mean), from its extreme samples.
std::vector<double> cycleAmplitudes(const std::vector<double>& y, double mean);

// Throws InputError when the record holds fewer than two whole cycles.
SeriesAnalysis analyseSeries(const ImportedSeries& series, double damping, double density, double speed,
                             double length, double side);

}  // namespace maris::fiv
