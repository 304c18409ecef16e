// Fatigue of the riser at its joints (section `fatigue`): the stress at 8 points around the circumference of
// every joint from tension and biaxial bending,
//   σ(θ) = SCF · (T/A_wall + (M_y′ sin θ − M_z′ cos θ)/W_B),   θ = 0°, 45°, …, 315° from the segment's y′ axis
// towards z′ (W_B = I/R_out: the outer fibre), rainflow-counted over the recorded history from
// fatigue.start_time on (core/fatigue), Miner damage on a DNVGL-RP-C203 (2016) curve with the thickness
// correction for the wall thickness, scaled to a year and inverted to a life.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "core/fatigue.hpp"
#include "core/results.hpp"
#include "core/schema_binder.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::riser {

// Per joint: its sampled tension [N] and bending stress components σ_xy = M_z′/W_B, σ_xz = M_y′/W_B [Pa].
struct JointStressSeries {
  double arc_length = 0.0;      // [m]
  double wall_area = 0.0;       // [m²]
  double wall_thickness = 0.0;  // [m]
  std::vector<double> tension, stress_xy, stress_xz;
};

struct JointFatigue {
  double arc_length = 0.0;      // [m]
  double damage = 0.0;          // [-] Miner sum over the counted window, at the worst point
  double damage_per_year = 0.0; // [1/yr] damage × (one year / window)
  double life = 0.0;            // [yr] 1 / damage_per_year (∞ when nothing is counted)
  int worst_point = 0;          // 0 … 7: θ = 45° × worst_point
};

// The `fatigue` section's fields (called by riserBinder) and the S–N curve they select.
void bindFatigueParameters(SchemaBinder<RiserParameters>& b);
fatigue::SnCurve fatigueCurve(const RiserParameters& p);
// How often the joint stresses are sampled for fatigue [s]: fatigue.sample_interval, or (0) 1/40 of the shortest
// forcing period (the harmonic top motion's, an Airy wave's period, half the peak period of a spectrum); 0 when
// fatigue is off or no forcing period is known (the history's samples are used). The integration samples at the
// finer of this and the history's spacing (riser_integration.cpp).
double fatigueSampleInterval(const RiserParameters& p);
// A user curve's slopes must meet at its transition (the field errors, appended to `errors`).
void checkFatigueParameters(const RiserParameters& p, std::vector<FieldError>& errors);

// The stress at point j (θ = 45° j) of one sample.
inline double hotSpotStress(const JointStressSeries& s, std::size_t sample, int point, double scf) {
  const double theta = 0.25 * 3.14159265358979323846 * point;
  return scf * (s.tension[sample] / s.wall_area - s.stress_xy[sample] * std::cos(theta) +
                s.stress_xz[sample] * std::sin(theta));
}

// Damage of every joint over the samples with time ≥ start_time (window = last time − first counted time > 0).
std::vector<JointFatigue> jointFatigue(const std::vector<double>& time, const std::vector<JointStressSeries>& joints,
                                       const fatigue::SnCurve& curve, double scf, double start_time);

// Table `fatigue` (arc length, damage, damage per year, life, worst angle), its life plot and the scalars
// min_fatigue_life and its hot spot (arc length, angle), added to `out`.
void addFatigueResults(const std::vector<JointFatigue>& joints, const fatigue::SnCurve& curve, double window,
                       Results& out);

}  // namespace maris::riser
