// Riser fatigue at the joints (contract in riser/riser_fatigue.hpp).
#include "riser/riser_fatigue.hpp"

#include "core/text_format.hpp"
#include "riser/riser_labels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace maris::riser {
namespace {
constexpr double kYear = 365.25 * 24.0 * 3600.0;  // [s]
constexpr double kLongestLife = 1e12;              // [yr] reported when (almost) nothing is counted
// A sine sampled k times a period has its range low by at most 1 − cos(π/k): 0.31 % at k = 40, so the damage by
// at most 0.9 % (m = 3) or 1.5 % (m = 5) from sampling.
constexpr double kFatigueSamplesPerPeriod = 40.0;
// At most this many joint-sample pairs (three doubles each: 1.2 GB): a 3-hour sea at n = 100 needs 8.6e6.
constexpr double kMaxFatigueValues = 5e7;
}  // namespace

void bindFatigueParameters(SchemaBinder<RiserParameters>& b) {
  using P = RiserParameters;
  b.boolean("fatigue.enabled", &P::fatigue_enabled,
            "Fatigue at every joint: stress at 8 points around the circumference from tension and biaxial bending, "
            "rainflow counting and Miner damage (table fatigue)");
  std::vector<std::string> curves = fatigue::dnvCurveNames();
  curves.emplace_back("user");
  b.choice("fatigue.sn_curve", &P::fatigue_sn_curve, curves,
           "DNVGL-RP-C203 (2016) S-N curve (thickness correction from the wall thickness, t_ref = 25 mm), or user "
           "(the fatigue.user_* fields)");
  b.choice("fatigue.environment", &P::fatigue_environment,
           {"air", "seawater_cathodic_protection", "seawater_free_corrosion"},
           "S-N curve table: in air (Table 2-1), in seawater with cathodic protection (Table 2-2) or in seawater for "
           "free corrosion (one slope, m = 3); not used by a user curve");
  b.real("fatigue.sample_interval", &P::fatigue_sample_interval, "s", Range::nonNegative(),
         "Joint stresses are sampled this often for rainflow counting (0: 40 samples per shortest forcing period: "
         "the top motion's, the wave period or half the peak period of a spectrum; never coarser than the history)");
  b.real("fatigue.user_log_a1", &P::fatigue_user_log_a1, "-", Range::closed(1.0, 40.0),
         "User S-N curve: log10 a1 of its first slope, log N = log a1 - m1 log(stress range in MPa)");
  b.real("fatigue.user_m1", &P::fatigue_user_m1, "-", Range::closed(1.0, 20.0), "User S-N curve: first slope m1");
  b.real("fatigue.user_log_a2", &P::fatigue_user_log_a2, "-", Range::closed(1.0, 60.0),
         "User S-N curve: log10 a2 of its second slope (beyond the transition)");
  b.real("fatigue.user_m2", &P::fatigue_user_m2, "-", Range::closed(0.0, 20.0),
         "User S-N curve: second slope m2 beyond the transition (0: one slope at every N)");
  b.real("fatigue.user_transition_cycles", &P::fatigue_user_transition_cycles, "-", Range::closed(1.0, 1e12),
         "User S-N curve: cycles N where the slope changes");
  b.real("fatigue.user_thickness_exponent", &P::fatigue_user_thickness_exponent, "-", Range::closed(0.0, 1.0),
         "User S-N curve: thickness exponent k of the correction (max(t, t_ref)/t_ref)^k");
  b.real("fatigue.user_reference_thickness", &P::fatigue_user_reference_thickness, "mm", Range::positive(1000.0),
         "User S-N curve: reference thickness t_ref of the correction");
  b.real("fatigue.stress_concentration_factor", &P::fatigue_stress_concentration_factor, "-", Range::closed(1.0, 10.0),
         "Stress concentration factor on the nominal stress");
  b.real("fatigue.start_time", &P::fatigue_start_time, "s", Range::nonNegative(),
         "Cycles are counted from this time on (skip the start-up ramp)");
}

fatigue::SnCurve fatigueCurve(const RiserParameters& p) {
  if (p.fatigue_sn_curve == "user") {
    fatigue::SnCurve c;
    c.name = "user S-N curve";
    c.log_a1 = p.fatigue_user_log_a1;
    c.m1 = p.fatigue_user_m1;
    c.log_a2 = p.fatigue_user_log_a2;
    c.m2 = p.fatigue_user_m2;
    c.transition_cycles = p.fatigue_user_transition_cycles;
    c.thickness_exponent = p.fatigue_user_thickness_exponent;
    c.reference_thickness = p.fatigue_user_reference_thickness;
    return c;
  }
  const auto environment = p.fatigue_environment == "air"                       ? fatigue::SnEnvironment::Air
                           : p.fatigue_environment == "seawater_free_corrosion" ? fatigue::SnEnvironment::SeawaterFreeCorrosion
                                                                                : fatigue::SnEnvironment::SeawaterCathodicProtection;
  return fatigue::dnvCurve(p.fatigue_sn_curve, environment);
}

double fatigueSampleInterval(const RiserParameters& p) {
  if (!p.fatigue_enabled || p.end_time <= 0) return 0.0;
  if (p.fatigue_sample_interval > 0) return p.fatigue_sample_interval;
  double shortest = std::numeric_limits<double>::infinity();
  const bool harmonic_top = p.top_motion_table.empty() &&
                            (p.motion_amplitude_x != 0 || p.motion_amplitude_y != 0 || p.motion_amplitude_z != 0);
  if (harmonic_top) shortest = p.motion_period;
  if (p.wave_type == "airy") shortest = std::min(shortest, p.wave_period);
  if (p.wave_type == "jonswap" || p.wave_type == "pierson_moskowitz") shortest = std::min(shortest, 0.5 * p.wave_peak_period);
  if (p.wave_type == "spectrum_table" && !p.wave_spectrum_table.empty()) {
    const auto peak = std::max_element(p.wave_spectrum_table.begin(), p.wave_spectrum_table.end(),
                                       [](const WaveSpectrumRow& a, const WaveSpectrumRow& b) { return a.density < b.density; });
    if (peak->omega > 0) shortest = std::min(shortest, 0.5 * 2.0 * std::numbers::pi / peak->omega);
  }
  return std::isfinite(shortest) ? shortest / kFatigueSamplesPerPeriod : 0.0;
}

void checkFatigueParameters(const RiserParameters& p, std::vector<FieldError>& e) {
  // The joint-stress series are kept for rainflow counting: three doubles per joint and sample.
  if (const double interval = fatigueSampleInterval(p); interval > 0) {
    const double values = p.end_time / interval * std::max(p.segment_count, 1);
    if (!(values <= kMaxFatigueValues))
      e.push_back({"fatigue.sample_interval", numberText(p.fatigue_sample_interval),
                   formatText("%s gives %.3g samples × %d joints = %.3g stress values (at most %.3g, %.2g GB): "
                              "raise fatigue.sample_interval, shorten solver.end_time or use fewer segments",
                              p.fatigue_sample_interval > 0 ? "this interval" : "the automatic interval",
                              p.end_time / interval, p.segment_count, values, kMaxFatigueValues,
                              kMaxFatigueValues * 24 / 1e9)});
  }
  if (p.fatigue_sn_curve != "user" || p.fatigue_user_m2 == 0.0) return;
  // The two slopes must meet at N_t: a gap or an overlap there would make N jump with the stress range.
  const double log_nt = std::log10(p.fatigue_user_transition_cycles);
  const double log_range_t = (p.fatigue_user_log_a1 - log_nt) / p.fatigue_user_m1;
  const double continuous_log_a2 = log_nt + p.fatigue_user_m2 * log_range_t;
  if (std::abs(p.fatigue_user_log_a2 - continuous_log_a2) > 5e-3) {
    e.push_back({"fatigue.user_log_a2", numberText(p.fatigue_user_log_a2),
                 formatText("the two slopes must meet at fatigue.user_transition_cycles: log a2 = %.4f makes them "
                            "meet (within 0.005)", continuous_log_a2)});
  }
}

std::vector<JointFatigue> jointFatigue(const std::vector<double>& time, const std::vector<JointStressSeries>& joints,
                                       const fatigue::SnCurve& curve, double scf, double start_time) {
  std::size_t first = 0;
  while (first < time.size() && time[first] < start_time) ++first;
  const double window = first < time.size() ? time.back() - time[first] : 0.0;
  std::vector<JointFatigue> out;
  std::vector<double> stress;
  for (const JointStressSeries& s : joints) {
    JointFatigue f;
    f.arc_length = s.arc_length;
    for (int point = 0; point < 8; ++point) {
      stress.clear();
      for (std::size_t k = first; k < time.size(); ++k) stress.push_back(hotSpotStress(s, k, point, scf));
      const double damage = fatigue::minerDamage(fatigue::rainflow(stress), curve, 1e3 * s.wall_thickness);
      if (damage > f.damage) {
        f.damage = damage;
        f.worst_point = point;
      }
    }
    f.damage_per_year = window > 0.0 ? f.damage * kYear / window : 0.0;
    f.life = f.damage_per_year > 1.0 / kLongestLife ? 1.0 / f.damage_per_year : kLongestLife;
    out.push_back(f);
  }
  return out;
}

void addFatigueResults(const std::vector<JointFatigue>& joints, const fatigue::SnCurve& curve, double window,
                       Results& out) {
  std::vector<double> s, d, dy, life, angle;
  const JointFatigue* worst = nullptr;
  for (const JointFatigue& j : joints) {
    s.push_back(j.arc_length);
    d.push_back(j.damage);
    dy.push_back(j.damage_per_year);
    life.push_back(j.life);
    angle.push_back(45.0 * j.worst_point);
    if (!worst || j.life < worst->life) worst = &j;
  }
  Table t;
  t.name = "fatigue";
  t.title = "Fatigue damage at the joints (" + curve.name + ")";
  t.add("arc_length", "m", std::move(s), riserColumnLabel("arc_length"));
  t.add("damage", "-", std::move(d), riserColumnLabel("damage"));
  t.add("damage_per_year", "1/yr", std::move(dy), riserColumnLabel("damage_per_year"));
  t.add("life", "yr", std::move(life), riserColumnLabel("life"));
  t.add("hot_spot_angle", "deg", std::move(angle), riserColumnLabel("hot_spot_angle"));
  out.tables.push_back(std::move(t));
  out.plots.push_back(makePlot("fatigue_life", "Fatigue life along the riser", "fatigue", "arc_length", {"life"}, true));
  if (!worst) return;
  out.addScalar("min_fatigue_life", worst->life, "yr",
                "Shortest fatigue life over the joints (damage over " + numberText(window) +
                    " s scaled to a year; capped at 1e12 yr)", "Minimum fatigue life");
  // Not capped like the life: a scatter-diagram study adds these, weighted by each sea state's probability.
  out.addScalar("max_fatigue_damage_per_year", worst->damage_per_year, "1/yr",
                "Annual fatigue damage at the critical hot spot (this sea state held all year)", "Max. damage per year");
  out.addScalar("fatigue_hot_spot_arc_length", worst->arc_length, "m", "Arc length of the critical hot spot", "Hot spot s");
  out.addScalar("fatigue_hot_spot_angle", 45.0 * worst->worst_point, "deg",
                "Angle of the critical hot spot around the circumference, from the segment's y' axis towards z'", "Hot-spot angle");
}

}  // namespace maris::riser
