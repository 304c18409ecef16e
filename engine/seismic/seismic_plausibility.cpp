#include "seismic/seismic_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "core/text_format.hpp"
#include "seismic/seismic_solve.hpp"

namespace maris::seismic {

namespace {

constexpr double kPi = std::numbers::pi;
// The mesh has 10 elements per wavelength of the slowest wave at solver.cutoff_frequency (paper eq 28): content
// above f_cut travels with growing dispersion error. An input whose spectrum is still above 1 % of its peak
// beyond f_cut puts visible energy where the mesh does not resolve it (1 % is our choice of "visible").
constexpr double kBandEdgeFraction = 0.01;

std::string num(double v) { return formatText("%.4g", v); }

// Root of a function that falls through `level` between lo and hi (bisection to 1e-12 of the interval).
double crossing(const std::function<double(double)>& f, double level, double lo, double hi) {
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > level ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Input length [s] after its arrival at the origin: the Ricker is centred 1.5/f_p after it and symmetric
// (seismic_free_field_report.cpp); a record's length is not known without reading it.
double inputLength(const SeismicParameters& p) {
  if (p.input_kind == "ricker") return 3.0 / p.ricker_peak_frequency;
  if (p.input_kind == "pulse") return p.pulse_duration;
  return 0.0;
}

// Vertical travel time [s] from the seabed surface (y = 0) to the top of the model at the incident wave's own
// speed in each layer: a lower bound (oblique rays and conversions to slower waves take longer).
double riseTime(const SeismicParameters& p) {
  const bool pwave = p.wave_type == "P";
  double t = 0.0;
  if (p.model == "reef")
    for (const auto& l : p.layers) t += l.thickness / (pwave ? l.vp : l.vs);
  else if (p.include_water)
    t += p.water_depth / p.water_sound_speed;
  return t;
}

}  // namespace

double inputBandEdge(const SeismicParameters& p) {
  if (p.input_kind == "ricker") {
    // x = f/f_p; the spectrum normalised to its peak at x = 1 is x² e^{1−x²}, falling for x > 1.
    const auto ricker = [](double x) { return x * x * std::exp(1.0 - x * x); };
    return p.ricker_peak_frequency * crossing(ricker, kBandEdgeFraction, 1.0, 10.0);
  }
  if (p.input_kind == "pulse") {
    // Four equal cubic B-spline pieces: four boxes of width T/4 convolved, |U| ∝ sinc⁴(y), y = fT/4, falling
    // from 1 at y = 0 to its first zero at y = 1.
    const auto bspline = [](double y) {
      const double s = y > 0 ? std::sin(kPi * y) / (kPi * y) : 1.0;
      return s * s * s * s;
    };
    return 4.0 / p.pulse_duration * crossing(bspline, kBandEdgeFraction, 0.0, 1.0);
  }
  return 0.0;
}

std::vector<FieldError> seismicPlausibility(const SeismicParameters& p) {
  std::vector<FieldError> w;
  const double edge = inputBandEdge(p);
  if (edge > p.cutoff_frequency) {
    const bool ricker = p.input_kind == "ricker";
    w.push_back({ricker ? "input.ricker_peak_frequency" : "input.pulse_duration",
                 num(ricker ? p.ricker_peak_frequency : p.pulse_duration),
                 "the input's spectrum stays above 1 % of its peak up to " + num(edge) +
                     " Hz, beyond solver.cutoff_frequency = " + num(p.cutoff_frequency) +
                     " Hz that the mesh resolves (10 elements per wavelength): raise the cut-off or lower the "
                     "input's frequency"});
  }
  std::vector<double> angles = {p.angle_deg};
  angles.insert(angles.end(), p.sweep_angles_deg.begin(), p.sweep_angles_deg.end());
  double arrival = 0.0;
  for (const double angle : angles) {
    const FreeField field(seabedMaterial(p), waterLayer(p), waveType(p), angle * kPi / 180.0);
    arrival = std::max(arrival, arrivalAtOrigin(p, field));
  }
  const double needed = arrival + inputLength(p) + riseTime(p);
  if (p.duration < needed)
    w.push_back({"solver.duration", num(p.duration),
                 "shorter than " + num(needed) + " s, the least time for the incident wave to pass the top of the "
                     "model (arrival at the seabed origin " + num(arrival) + " s + input " + num(inputLength(p)) +
                     " s + vertical travel " + num(riseTime(p)) + " s): the response is cut off"});
  return w;
}

}  // namespace maris::seismic
