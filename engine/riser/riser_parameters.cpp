#include "riser/riser_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "riser/riser_fatigue.hpp"
#include "riser/riser_waves.hpp"

namespace maris::riser {
namespace {

using P = RiserParameters;

SchemaBinder<SectionRow> sectionBinder() {
  SchemaBinder<SectionRow> b;
  b.real("start", &SectionRow::start, "m", Range::nonNegative(), "Arc length from the top where the section begins");
  b.real("end", &SectionRow::end, "m", Range::positive(), "Arc length from the top where the section ends");
  b.real("outer_diameter", &SectionRow::outer_diameter, "m", Range::positive(20.0), "Outer diameter D_out");
  b.real("inner_diameter", &SectionRow::inner_diameter, "m", Range::nonNegative(20.0), "Inner diameter D_inn");
  b.real("youngs_modulus", &SectionRow::youngs_modulus, "Pa", Range::nonNegative(1e13), "Young's modulus E");
  b.real("shear_modulus", &SectionRow::shear_modulus, "Pa", Range::nonNegative(1e13), "Shear modulus G");
  b.real("density", &SectionRow::density, "kg/m^3", Range::positive(1e5), "Density of the wall");
  b.real("normal_drag_coefficient", &SectionRow::normal_drag_coefficient, "-", Range::closed(0, 10),
         "Normal Morison drag coefficient D_yz");
  b.real("tangential_drag_coefficient", &SectionRow::tangential_drag_coefficient, "-", Range::closed(0, 10),
         "Tangential drag coefficient D_x (on D_out)");
  b.real("added_mass_coefficient", &SectionRow::added_mass_coefficient, "-", Range::closed(0, 10),
         "Added-mass coefficient C_a = c_M - 1");
  return b;
}

SchemaBinder<PointLoadRow> pointLoadBinder() {
  SchemaBinder<PointLoadRow> b;
  b.integer("node", &PointLoadRow::node, "-", Range::closed(0, 5001), "Node: 0 top, k joint k, n+1 bottom end");
  b.real("force_x", &PointLoadRow::force_x, "N", Range::any(), "Force, global x");
  b.real("force_y", &PointLoadRow::force_y, "N", Range::any(), "Force, global y");
  b.real("force_z", &PointLoadRow::force_z, "N", Range::any(), "Force, global z (up)");
  b.real("moment_x", &PointLoadRow::moment_x, "N*m", Range::any(), "Moment about global x");
  b.real("moment_y", &PointLoadRow::moment_y, "N*m", Range::any(), "Moment about global y");
  b.real("moment_z", &PointLoadRow::moment_z, "N*m", Range::any(), "Moment about global z");
  b.real("start_time", &PointLoadRow::start_time, "s", Range::nonNegative(), "Load switched on");
  b.real("end_time", &PointLoadRow::end_time, "s", Range::nonNegative(), "Load switched off");
  return b;
}

SchemaBinder<TopMotionRow> topMotionBinder() {
  SchemaBinder<TopMotionRow> b;
  b.real("time", &TopMotionRow::time, "s", Range::nonNegative(), "Time of the row");
  b.real("x", &TopMotionRow::x, "m", Range::closed(-1e4, 1e4), "Top displacement from top.x");
  b.real("y", &TopMotionRow::y, "m", Range::closed(-1e4, 1e4), "Top displacement from top.y");
  b.real("z", &TopMotionRow::z, "m", Range::closed(-1e4, 1e4), "Top displacement from top.z (not for a tensioner)");
  return b;
}

SchemaBinder<ProbeRow> probeBinder() {
  SchemaBinder<ProbeRow> b;
  b.real("arc_length", &ProbeRow::arc_length, "m", Range::nonNegative(), "Arc length of the probe from the top");
  return b;
}

SchemaBinder<P> makeBinder() {
  SchemaBinder<P> b;
  b.real("geometry.length", &P::length, "m", Range::positive(1e5), "Length L of the riser or cable");
  b.integer("geometry.segment_count", &P::segment_count, "-", Range::closed(2, 5000),
            "Primary elements n (n+1 rigid segments, n spring-damping elements)");
  b.real("section.outer_diameter", &P::outer_diameter, "m", Range::positive(20.0), "Outer diameter D_out");
  b.real("section.inner_diameter", &P::inner_diameter, "m", Range::nonNegative(20.0), "Inner diameter D_inn");
  b.real("section.youngs_modulus", &P::youngs_modulus, "Pa", Range::nonNegative(1e13), "Young's modulus E");
  b.real("section.shear_modulus", &P::shear_modulus, "Pa", Range::nonNegative(1e13), "Shear modulus G");
  b.real("section.density", &P::density, "kg/m^3", Range::positive(1e5), "Density of the pipe wall");
  b.real("section.normal_drag_coefficient", &P::normal_drag_coefficient, "-", Range::closed(0, 10),
         "Normal Morison drag coefficient D_yz (on D_out)");
  b.real("section.tangential_drag_coefficient", &P::tangential_drag_coefficient, "-", Range::closed(0, 10),
         "Tangential drag coefficient D_x (on D_out, eq 34)");
  b.real("section.added_mass_coefficient", &P::added_mass_coefficient, "-", Range::closed(0, 10),
         "Added-mass coefficient C_a = c_M - 1 (isotropic, eq 11)");
  b.table("sections", &P::sections, sectionBinder(), 0, 1000, "Stretches with their own section properties");
  b.choice("model.formulation", &P::formulation, {"joint", "absolute"},
           "Coordinates: joint (J, continuity exact) or absolute (A, constraints with Baumgarte stabilisation)");
  b.boolean("model.torsion", &P::torsion, "Torsion on (J3/A3) or off (J2/A2: segments do not spin about their axes)");
  b.real("model.stiffness_damping", &P::stiffness_damping, "s", Range::nonNegative(10.0),
         "Stiffness-proportional spring damping β: damping moments = β·C·(relative angle rates)");
  b.real("environment.gravity", &P::gravity, "m/s^2", Range::nonNegative(100.0), "Gravitational acceleration");
  b.real("environment.water_density", &P::water_density, "kg/m^3", Range::nonNegative(1e4), "Sea water density");
  b.real("environment.water_level", &P::water_level, "m", Range::any(), "z of the still-water surface");
  b.real("environment.seabed_level", &P::seabed_level, "m", Range::any(), "z of the sea bed (drawn)");
  b.real("environment.internal_fluid_density", &P::internal_fluid_density, "kg/m^3", Range::nonNegative(1e5),
         "Density of the contents");
  b.real("environment.internal_flow_speed", &P::internal_flow_speed, "m/s", Range::closed(-100, 100),
         "Constant flow speed u of the contents along the riser (> 0 from top to bottom; eqs 43-52)");
  b.real("current.speed_surface", &P::current_speed_surface, "m/s", Range::closed(-20, 20), "Current at the surface");
  b.real("current.speed_seabed", &P::current_speed_seabed, "m/s", Range::closed(-20, 20), "Current at the sea bed");
  b.real("current.direction", &P::current_direction, "rad", Range::closed(-7, 7), "Current heading from +x to +y");
  b.choice("top.condition", &P::top_condition, {"pinned", "clamped", "tensioner", "free"},
           "Top end: ball joint, clamp, tensioner (vertical force, horizontal motion prescribed) or free");
  b.real("top.x", &P::top_x, "m", Range::any(), "Mean top position x");
  b.real("top.y", &P::top_y, "m", Range::any(), "Mean top position y");
  b.real("top.z", &P::top_z, "m", Range::any(), "Mean top position z (ignored for the tensioner)");
  b.real("top.tension", &P::top_tension, "N", Range::nonNegative(1e10), "Tensioner pull (upward)");
  b.real("top.motion_amplitude_x", &P::motion_amplitude_x, "m", Range::nonNegative(1e3), "Top motion amplitude x");
  b.real("top.motion_amplitude_y", &P::motion_amplitude_y, "m", Range::nonNegative(1e3), "Top motion amplitude y");
  b.real("top.motion_amplitude_z", &P::motion_amplitude_z, "m", Range::nonNegative(1e3), "Top motion amplitude z");
  b.real("top.motion_period", &P::motion_period, "s", Range::positive(1e5), "Top motion period");
  b.real("top.motion_phase_x", &P::motion_phase_x, "rad", Range::closed(-7, 7), "Phase of the x motion");
  b.real("top.motion_phase_y", &P::motion_phase_y, "rad", Range::closed(-7, 7), "Phase of the y motion");
  b.real("top.motion_phase_z", &P::motion_phase_z, "rad", Range::closed(-7, 7), "Phase of the z motion");
  b.real("top.motion_ramp_time", &P::motion_ramp_time, "s", Range::nonNegative(1e5), "Smooth start of the motion");
  b.choice("top.motion", &P::top_motion, {"harmonic", "table"},
           "Top motion: harmonic per axis (amplitudes, period, phases) or the time table top_motion_table");
  b.table("top_motion_table", &P::top_motion_table, topMotionBinder(), 0, 100000,
          "Top displacement over time (clamped cubic spline; first/last row held outside the table)");
  b.choice("bottom.condition", &P::bottom_condition, {"pinned", "clamped", "free", "spring"},
           "Bottom end: ball joint at the anchor, clamp, free, or linear spring to the anchor");
  b.real("bottom.x", &P::bottom_x, "m", Range::any(), "Anchor x");
  b.real("bottom.y", &P::bottom_y, "m", Range::any(), "Anchor y");
  b.real("bottom.z", &P::bottom_z, "m", Range::any(), "Anchor z");
  b.real("bottom.spring_stiffness", &P::bottom_spring_stiffness, "N/m", Range::nonNegative(1e12), "Anchor spring");
  b.real("bottom.spring_damping", &P::bottom_spring_damping, "N*s/m", Range::nonNegative(1e12), "Anchor damper");
  b.real("initial.inclination", &P::initial_inclination, "rad", Range::closed(0, 3.1416),
         "Initial direction from the top, measured from straight down (free or spring bottom)");
  b.real("initial.azimuth", &P::initial_azimuth, "rad", Range::closed(-7, 7), "Heading of the initial direction");
  b.boolean("initial.solve_statics", &P::solve_statics, "Start from static equilibrium");
  bindWaveParameters(b);
  bindFatigueParameters(b);
  b.table("point_loads", &P::point_loads, pointLoadBinder(), 0, 1000, "Forces and moments at nodes (box pulses)");
  b.real("solver.end_time", &P::end_time, "s", Range::nonNegative(1e6), "Simulated time");
  b.real("solver.time_step", &P::time_step, "s", Range::nonNegative(10.0),
         "Step of rk4; largest step of implicit, which cuts each output interval into equal steps (0 = automatic: "
         "rk4 half its stability limit, implicit from the tolerance)");
  b.choice("solver.integrator", &P::integrator, {"auto", "rk4", "dopri5", "implicit"},
           "Time integrator: rk4 (constant step, the paper's), dopri5 (adaptive), implicit (stiff torsion), "
           "auto (the cheapest for the tolerance)");
  b.real("solver.tolerance", &P::tolerance, "-", Range::closed(1e-12, 1e-1),
         "Relative local error tolerance of dopri5; the implicit Newton iteration converges to 1e-3 of it, or of "
         "the step's expected error if that is larger (within 1e-10 and 1e-6)");
  b.integer("output.frame_count", &P::frame_count, "-", Range::closed(1, 10000), "Stored frames");
  b.table("output.probes", &P::probes, probeBinder(), 1, 20,
          "Probe points (arc length from the top) whose displacement and stress histories are recorded");
  b.realList("output.stress_times", &P::stress_times, "s", Range::nonNegative(), 0, 100,
             "Times of the stress-along-the-riser tables");
  b.realList("frequency_sweep.pretension_ratios", &P::sweep_pretension_ratios, "-", Range::closed(0.0, 1000.0), 0, 100,
             "Pretension ratios i_T to sweep (tensioner: T = i_T g m', m' the submerged mass of riser and contents); "
             "each gives the first two bending frequencies (table frequency_vs_pretension)");
  b.realList("frequency_sweep.segment_counts", &P::sweep_segment_counts, "-", Range::closed(2.0, 200.0), 0, 100,
             "Segment counts n to sweep at top.tension (whole numbers; table frequency_vs_segments)");
  b.realList("stress_convergence.segment_counts", &P::convergence_segment_counts, "-", Range::closed(2.0, 1000.0), 0,
             20,
             "Segment counts n at which the whole run is repeated to show how the first probe's bending stress "
             "converges (whole numbers; table bending_stress_vs_segments)");
  b.real("stress_convergence.tolerance", &P::convergence_tolerance, "-", Range::closed(1e-6, 1e-2),
         "Under a harmonic top motion each repeated run is integrated by generalized-α with its step from this "
         "expected probe error (relative to the motion; keep it below the differences between the n); other runs "
         "keep the solver settings, so a fixed rk4 step must be stable at every n");
  return b;
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

const SchemaBinder<RiserParameters>& riserBinder() {
  static const SchemaBinder<RiserParameters> binder = makeBinder();
  return binder;
}

std::vector<FieldError> checkRiserParameters(const RiserParameters& p) {
  std::vector<FieldError> e;
  if (p.inner_diameter >= p.outer_diameter)
    e.push_back({"section.inner_diameter", num(p.inner_diameter),
                 "must be smaller than section.outer_diameter = " + num(p.outer_diameter)});
  for (std::size_t k = 0; k < p.sections.size(); ++k) {
    const auto& s = p.sections[k];
    const std::string at = "sections[" + std::to_string(k) + "]";
    if (s.inner_diameter >= s.outer_diameter)
      e.push_back({at + ".inner_diameter", num(s.inner_diameter),
                   "must be smaller than outer_diameter = " + num(s.outer_diameter)});
    if (s.end <= s.start)
      e.push_back({at + ".end", num(s.end), "must be greater than start = " + num(s.start)});
    if (s.start >= p.length)
      e.push_back({at + ".start", num(s.start), "must be in [0, " + num(p.length) + ") (geometry.length)"});
  }
  const int last_node = p.segment_count + 1;
  for (std::size_t k = 0; k < p.point_loads.size(); ++k) {
    const auto& l = p.point_loads[k];
    const std::string at = "point_loads[" + std::to_string(k) + "]";
    if (l.node > last_node)
      e.push_back({at + ".node", std::to_string(l.node), "must be in [0, " + std::to_string(last_node) + "]"});
    if (l.end_time < l.start_time)
      e.push_back({at + ".end_time", num(l.end_time), "must not be before start_time = " + num(l.start_time)});
  }
  if (p.top_motion == "table") {
    if (p.top_motion_table.size() < 2)
      e.push_back({"top_motion_table", std::to_string(p.top_motion_table.size()) + " rows",
                   "top.motion = table needs at least 2 rows"});
    for (std::size_t k = 1; k < p.top_motion_table.size(); ++k)
      if (!(p.top_motion_table[k].time > p.top_motion_table[k - 1].time))
        e.push_back({"top_motion_table[" + std::to_string(k) + "].time", num(p.top_motion_table[k].time),
                     "must be greater than the previous row's time " + num(p.top_motion_table[k - 1].time)});
  }
  for (std::size_t k = 0; k < p.probes.size(); ++k)
    if (p.probes[k].arc_length > p.length)
      e.push_back({"output.probes[" + std::to_string(k) + "].arc_length", num(p.probes[k].arc_length),
                   "must be in [0, " + num(p.length) + "] (geometry.length)"});
  // An inextensible chain cannot reach an anchor farther than its length; exactly L is a singular (taut) system.
  const bool fixed_bottom = p.bottom_condition == "pinned" || p.bottom_condition == "clamped";
  if (fixed_bottom && (p.top_condition == "pinned" || p.top_condition == "clamped")) {
    const double chord = std::hypot(std::hypot(p.bottom_x - p.top_x, p.bottom_y - p.top_y), p.bottom_z - p.top_z);
    if (chord > 0.999 * p.length)
      e.push_back({"bottom.z", num(p.bottom_z),
                   "anchor is " + num(chord) + " m from the top: must be closer than 0.999·L = " +
                       num(0.999 * p.length) + " m (inextensible segments; use top.condition = tensioner)"});
  }
  if (fixed_bottom && p.top_condition == "tensioner") {
    const double horizontal = std::hypot(p.bottom_x - p.top_x, p.bottom_y - p.top_y);
    if (horizontal > 0.9 * p.length)
      e.push_back({"bottom.x", num(p.bottom_x), "horizontal offset " + num(horizontal) +
                                                    " m from the top must be below 0.9·L = " + num(0.9 * p.length)});
  }
  if (p.top_condition == "tensioner" && !fixed_bottom)
    e.push_back({"top.condition", "\"tensioner\"", "a tensioner needs bottom.condition pinned or clamped"});
  if (p.top_condition == "free" && p.bottom_condition == "free" && p.gravity == 0.0 && p.point_loads.empty())
    e.push_back({"top.condition", "\"free\"", "both ends free with no gravity and no loads: nothing to compute"});
  if (p.top_condition == "clamped" && p.bottom_condition == "clamped" && p.segment_count < 3)
    e.push_back({"geometry.segment_count", std::to_string(p.segment_count), "must be >= 3 with both ends clamped"});
  // Frequency sweeps: i_T scales the tensioner's pull; n must be whole.
  if (!p.sweep_pretension_ratios.empty() && p.top_condition != "tensioner")
    e.push_back({"frequency_sweep.pretension_ratios", std::to_string(p.sweep_pretension_ratios.size()) + " values",
                 "a pretension sweep needs top.condition = tensioner (now \"" + p.top_condition + "\")"});
  for (std::size_t k = 0; k < p.sweep_segment_counts.size(); ++k)
    if (p.sweep_segment_counts[k] != std::round(p.sweep_segment_counts[k]))
      e.push_back({"frequency_sweep.segment_counts[" + std::to_string(k) + "]", num(p.sweep_segment_counts[k]),
                   "must be a whole number in [2, 200]"});
  for (std::size_t k = 0; k < p.convergence_segment_counts.size(); ++k)
    if (p.convergence_segment_counts[k] != std::round(p.convergence_segment_counts[k]))
      e.push_back({"stress_convergence.segment_counts[" + std::to_string(k) + "]", num(p.convergence_segment_counts[k]),
                   "must be a whole number in [2, 1000]"});
  if (!p.convergence_segment_counts.empty() && p.end_time <= 0)
    e.push_back({"solver.end_time", num(p.end_time), "a stress convergence study repeats the time history: must be > 0"});
  checkWaveParameters(p, e);
  if (p.fatigue_enabled && p.fatigue_start_time >= p.end_time)
    e.push_back({"fatigue.start_time", num(p.fatigue_start_time),
                 "must be before solver.end_time = " + num(p.end_time) + " (no cycles would be counted)"});
  if ((!p.sweep_pretension_ratios.empty() || !p.sweep_segment_counts.empty()) && !p.solve_statics)
    e.push_back({"initial.solve_statics", "false", "frequency sweeps linearise about the static state: must be true"});
  // Each convergence row is a whole run at its n: fields that depend on n (point load nodes, both ends clamped) must
  // hold there too. A field the scenario already has an error on at its own n is not named again per row (its message
  // may differ with n: "must be in [0, 101]" against "[0, 51]").
  const std::vector<FieldError> own = e;
  auto repeated = [&own](const FieldError& r) {
    return std::any_of(own.begin(), own.end(), [&r](const FieldError& o) { return o.path == r.path; });
  };
  for (std::size_t k = 0; k < p.convergence_segment_counts.size(); ++k) {
    const double n = p.convergence_segment_counts[k];
    if (n != std::round(n) || n == p.segment_count) continue;
    RiserParameters row = p;
    row.segment_count = static_cast<int>(n);
    row.convergence_segment_counts.clear();
    for (const FieldError& r : checkRiserParameters(row))
      if (!repeated(r))
        e.push_back({"stress_convergence.segment_counts[" + std::to_string(k) + "]", num(n),
                     "at this n, " + r.path + " = " + r.value + ": " + r.message});
  }
  return e;
}

std::vector<std::string> upgradeRiserParameters(Json& parameters) {
  std::vector<std::string> notes;
  // Scenarios written before the stress convergence study existed have no such section: no study.
  if (parameters.is_object() && !parameters.contains("stress_convergence")) {
    parameters["stress_convergence"] = riserBinder().write(RiserParameters{})["stress_convergence"];
    notes.push_back("stress_convergence added without a study (new in the riser schema; save the scenario to keep it)");
  }
  if (parameters.is_object() && !parameters.contains("fatigue")) {
    parameters["fatigue"] = riserBinder().write(RiserParameters{})["fatigue"];
    notes.push_back("fatigue added, off (new in the riser schema; save the scenario to keep it)");
  }
  if (parameters.is_object() && !parameters.contains("waves")) {
    parameters["waves"] = riserBinder().write(RiserParameters{})["waves"];
    notes.push_back("waves added as none (new in the riser schema; save the scenario to keep it)");
  }
  auto output = parameters.find("output");
  if (output == parameters.end() || !output->is_object()) return notes;
  auto old = output->find("probe_position");
  if (old == output->end()) return notes;
  if (output->contains("probes")) {
    notes.push_back("output.probe_position = " + old->dump() + " ignored: output.probes is given");
  } else {
    (*output)["probes"] = Json::array({Json{{"arc_length", *old}}});
    notes.push_back("output.probe_position = " + old->dump() + " read as output.probes = [{\"arc_length\": " +
                    old->dump() + "}] (renamed in the riser schema; save the scenario to update it)");
  }
  output->erase(old);
  return notes;
}

}  // namespace maris::riser
