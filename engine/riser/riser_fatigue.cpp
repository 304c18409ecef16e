// Riser fatigue at the joints (contract in riser/riser_fatigue.hpp).
#include "riser/riser_labels.hpp"
#include "riser/riser_fatigue.hpp"

#include <algorithm>
#include <cmath>

namespace maris::riser {
namespace {
constexpr double kYear = 365.25 * 24.0 * 3600.0;  // [s]
constexpr double kLongestLife = 1e12;              // [yr] reported when (almost) nothing is counted
}  // namespace

void bindFatigueParameters(SchemaBinder<RiserParameters>& b) {
  using P = RiserParameters;
  b.boolean("fatigue.enabled", &P::fatigue_enabled,
            "Fatigue at every joint: stress at 8 points around the circumference from tension and biaxial bending, "
            "rainflow counting and Miner damage (table fatigue)");
  b.choice("fatigue.sn_curve", &P::fatigue_sn_curve, fatigue::dnvCurveNames(),
           "DNVGL-RP-C203 (2016) S-N curve (thickness correction from the wall thickness, t_ref = 25 mm)");
  b.choice("fatigue.environment", &P::fatigue_environment, {"air", "seawater_cathodic_protection"},
           "S-N curve table: in air (Table 2-1) or in seawater with cathodic protection (Table 2-2)");
  b.real("fatigue.stress_concentration_factor", &P::fatigue_stress_concentration_factor, "-", Range::closed(1.0, 10.0),
         "Stress concentration factor on the nominal stress");
  b.real("fatigue.start_time", &P::fatigue_start_time, "s", Range::nonNegative(),
         "Cycles are counted from this time on (skip the start-up ramp)");
}

fatigue::SnCurve fatigueCurve(const RiserParameters& p) {
  return fatigue::dnvCurve(p.fatigue_sn_curve, p.fatigue_environment == "air"
                                                   ? fatigue::SnEnvironment::Air
                                                   : fatigue::SnEnvironment::SeawaterCathodicProtection);
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
                "Shortest fatigue life over the joints (damage over " + std::to_string(window) +
                    " s scaled to a year; capped at 1e12 yr)", "Minimum fatigue life");
  // Not capped like the life: a scatter-diagram study adds these, weighted by each sea state's probability.
  out.addScalar("max_fatigue_damage_per_year", worst->damage_per_year, "1/yr",
                "Annual fatigue damage at the critical hot spot (this sea state held all year)", "Max. damage per year");
  out.addScalar("fatigue_hot_spot_arc_length", worst->arc_length, "m", "Arc length of the critical hot spot", "Hot spot s");
  out.addScalar("fatigue_hot_spot_angle", 45.0 * worst->worst_point, "deg",
                "Angle of the critical hot spot around the circumference, from the segment's y' axis towards z'", "Hot-spot angle");
}

}  // namespace maris::riser
