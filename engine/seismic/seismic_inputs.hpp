// Incident-wave time functions: the displacement u0(t) of the incident wave at the origin.
//   - the paper's 0.2 s pulse, read as Liu's cubic B-spline displacement pulse (the text does not
//     give its form): unit peak at T/2, spectrum [sin(πfT/4)/(πfT/4)]^4 with its first zero at 4/T;
//   - a Ricker wavelet (displacement), peak frequency f_p, centred at t_c;
//   - a recorded accelerogram: a table of time [s], acceleration [m/s^2] (core/table_reader.hpp) or a PEER
//     .AT2 record (core/formats/peer_at2.hpp, g to m/s^2 with g = 9.80665), baseline-corrected, scaled to a
//     target peak acceleration and integrated twice.
#pragma once

#include <string>
#include <vector>

namespace maris::seismic {

// Cubic B-spline pulse of duration T [s] starting at t = 0, unit peak at T/2 [m per m].
double bsplinePulse(double t, double duration);

// Ricker wavelet (1 − 2π²f²τ²)·exp(−π²f²τ²), τ = t − t_centre; unit peak [m per m].
double rickerWavelet(double t, double peak_frequency, double centre);

// A record after correction, on a uniform grid t_k = k·dt.
struct Accelerogram {
  double dt = 0.0;                    // [s]
  std::vector<double> acceleration;   // [m/s^2] baseline-corrected, scaled
  std::vector<double> velocity;       // [m/s]
  std::vector<double> displacement;   // [m]
  double final_velocity_before = 0.0; // [m/s] end velocity of the raw record (what the correction removed)
};

// Reads "time, acceleration" rows (a header line and '#' comments are skipped; ',' ';' or blanks
// separate), resamples linearly to dt, removes a least-squares quadratic baseline from the
// displacement (so the corrected record ends at rest), and scales it to |a|max = peak_acceleration.
// A path "builtin:<name>.csv" reads resources/data/seismic/<name>.csv embedded in the engine
// (builtin:synthetic_kanai_tajimi.csv, a synthetic record: see the header of that file).
// Throws InputError naming `field` on an unreadable file, fewer than 8 rows, non-increasing time
// or an all-zero record.
Accelerogram loadAccelerogram(const std::string& path, double dt, double peak_acceleration, const std::string& field);

// Same correction and scaling for samples already in memory (time, acceleration).
Accelerogram correctAccelerogram(const std::vector<double>& time, const std::vector<double>& acceleration, double dt,
                                 double peak_acceleration, const std::string& field);

}  // namespace maris::seismic
