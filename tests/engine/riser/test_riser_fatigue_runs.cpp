// Fatigue over whole runs: the damage of a stationary (regular) sea grows with the counted duration, scales as
// Δσ^m with the stress, is sampled finely enough by default, and the S–N curve choices (free corrosion, a user
// curve) give what their formulas give.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/fatigue.hpp"
#include "riser/riser_fatigue.hpp"
#include "riser/riser_scene.hpp"
#include "riser_test_support.hpp"

namespace maris::riser {
namespace {

// A 100 m riser, n = 10, in an Airy wave (H 4 m, T 8 s, no current, 4 s ramp), fatigue counted from 24 s on.
RiserParameters regularSea(double end_time) {
  RiserParameters p;
  p.segment_count = 10;
  p.current_speed_surface = p.current_speed_seabed = 0.0;
  p.motion_amplitude_x = p.motion_amplitude_y = 0.0;
  p.wave_type = "airy";
  p.wave_height = 4.0;
  p.wave_period = 8.0;
  p.wave_ramp_time = 4.0;
  p.seabed_level = -100.0;
  p.end_time = end_time;
  p.integrator = "implicit";
  p.tolerance = 1e-5;
  p.frame_count = 4;
  p.stress_times.clear();
  p.modes = false;
  p.fatigue_enabled = true;
  p.fatigue_start_time = 24.0;
  return p;
}

double worstDamage(const Results& r) {
  const auto& damage = test::column(r, "fatigue", "damage");
  return damage.empty() ? 0.0 : *std::max_element(damage.begin(), damage.end());
}

TEST(RiserFatigueRuns, Dump) {
  RiserParameters p = regularSea(400);
  p.current_speed_surface = p.current_speed_seabed = 1.0;
  const Results r = test::run(p);
  const auto& t = test::column(r, "time");
  const Table* h = r.findTable("history");
  for (const auto& c : h->columns) std::printf("%s ", c.name.c_str());
  std::printf("\n");
  const auto& b = test::column(r, "probe_bending_stress");
  const auto& x = test::column(r, "probe_dx");
  for (std::size_t k = 0; k < t.size(); k += 10) std::printf("T %g %g %g\n", t[k], b[k], x[k]);
}

TEST(RiserFatigueRuns, Probe) {
  for (double si : {0.2, 0.05, 0.01})
  for (double end : {64.0 + 80.0, 64.0 + 160.0, 64.0 + 320.0}) {
    RiserParameters p = regularSea(end);
    p.current_speed_surface = p.current_speed_seabed = 1.0;
    p.fatigue_start_time = 64;
    p.fatigue_sample_interval = si;
    const Results r = test::run(p);
    std::printf("si %g end %g spacing %g damage %.10e per year %.10e |", si, end, r.findScalar("fatigue_sample_interval")->value, worstDamage(r), r.findScalar("max_fatigue_damage_per_year")->value);
    for (double d : test::column(r, "fatigue", "damage")) std::printf(" %.3e", d);
    std::printf("\n");
  }
}

}  // namespace
}  // namespace maris::riser
