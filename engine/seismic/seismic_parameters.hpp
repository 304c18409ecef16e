// Parameters of the seismic scene (reef–seawater system under oblique P/SV waves), SI units.
// Defaults are an assumed placeholder reef (NOT the paper's Table 1,
// which the available text lacks) with a Ricker input that the default 5 Hz mesh resolves.
#pragma once

#include <string>
#include <vector>

#include "core/schema_binder.hpp"
#include "seismic/free_field.hpp"

namespace maris::seismic {

// One reef-rock layer; layers are listed from the top (layer 1, the reef flat) down.
struct ReefLayer {
  double thickness = 100.0;  // [m] vertical extent of the layer
  double slope_deg = 45.0;   // [deg] slope of its flank from the horizontal
  double density = 2000.0;   // [kg/m^3]
  double vs = 800.0;         // [m/s] S-wave speed
  double vp = 1496.6;        // [m/s] P-wave speed (ν = 0.30 in the placeholder)
};

struct SeismicParameters {
  // Model: "reef" (layered reef on the seabed) or "box" (no topography: the paper's verification box).
  std::string model = "reef";
  bool include_water = true;          // false: the paper's "sloping platform" (water and its boundary removed)
  bool compare_without_water = true;  // also run without water and report the deviation δ

  // Incidence
  std::string wave_type = "P";               // "P" or "SV"
  double angle_deg = 30.0;                   // [deg] from the vertical, > 0: wave travels towards +x
  std::vector<double> sweep_angles_deg = {};  // [deg] extra angles, one thread each (reef amplification only)

  // Input: incident displacement at the origin
  std::string input_kind = "ricker";        // "pulse" (paper's 0.2 s B-spline), "ricker", "accelerogram"
  double pulse_duration = 0.2;              // [s] B-spline pulse length
  double ricker_peak_frequency = 1.5;       // [Hz]
  double input_amplitude = 0.01;            // [m] peak incident displacement (pulse, Ricker)
  std::string accelerogram_file = "";       // CSV time [s], acceleration [m/s^2]
  double accelerogram_peak_acceleration = 1.0;  // [m/s^2] the record is scaled to this peak

  // Seabed half-space
  double seabed_density = 2700.0;  // [kg/m^3]
  double seabed_vs = 2000.0;       // [m/s]
  double seabed_vp = 4546.0;       // [m/s] (ν = 0.38, from the paper's SV limit 26.1°)

  // Water
  double water_density = 1025.0;     // [kg/m^3] (paper)
  double water_sound_speed = 1450.0; // [m/s] (paper)
  double water_depth = 600.0;        // [m] at the lateral boundaries

  // Geometry
  double flat_width = 800.0;           // [m] L, reef flat
  double lateral_water_width = 1000.0; // [m] water between the reef toe and each lateral boundary (box: half-width)
  double seabed_thickness = 600.0;     // [m] H_s, seabed depth modelled below y = 0
  std::vector<ReefLayer> layers = {
      {100.0, 45.0, 2000.0, 800.0, 1496.6}, {200.0, 40.0, 2300.0, 1400.0, 2619.1}, {300.0, 35.0, 2500.0, 1800.0, 3367.4}};

  // Discretisation and run
  double cutoff_frequency = 5.0;  // [Hz] f_cut: element size Δ ≤ v_min/(10 f_cut) (paper eq 28)
  double duration = 6.0;          // [s] simulated time
  double courant_fraction = 0.8;  // [-] time step / stable step; > 1 is refused
  int snapshot_count = 16;        // [-] wave-field frames in the 3D view
  int station_count = 41;         // [-] stations along the reef flat

  // Modal analysis of the reef + seabed (+ the water when include_water: fluid–solid modes), reef model only
  int mode_count = 10;              // [-] lowest modes reported; 0 skips the analysis
  std::string modal_base = "fixed"; // "fixed": bottom clamped, or "springs": boundary springs only
};

SchemaBinder<SeismicParameters> seismicBinder();

// Cross-field checks: vp/vs, SV critical angle, water depth vs reef, mesh size limits.
std::vector<FieldError> checkSeismicParameters(const SeismicParameters& p);

// Outer box of the model [m]: x ∈ [−half_width, half_width], y ∈ [−seabed_thickness, top].
struct ModelExtent {
  double half_width = 0.0;    // [m]
  double seabed_depth = 0.0;  // [m] H_s (bottom at y = −H_s)
  double top = 0.0;           // [m] highest point: water surface or reef flat
  double reef_height = 0.0;   // [m] sum of layer thicknesses (0 for the box)
  double reef_half_base = 0.0;  // [m] half-width of the reef at the seabed
};
ModelExtent modelExtent(const SeismicParameters& p);
// Smallest wave speed in the model [m/s] (S in the solids, sound in the water): sets the mesh size.
double slowestSpeed(const SeismicParameters& p);

// Converters used by the solver.
ElasticMaterial seabedMaterial(const SeismicParameters& p);
WaterLayer waterLayer(const SeismicParameters& p);  // depth 0 when include_water is false
WaveType waveType(const SeismicParameters& p);

}  // namespace maris::seismic
