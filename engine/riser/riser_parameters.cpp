#include "riser/riser_parameters.hpp"

#include "core/angles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "riser/riser_buoyancy.hpp"
#include "riser/riser_current.hpp"
#include "riser/riser_fatigue.hpp"
#include "riser/riser_seabed.hpp"
#include "riser/riser_vessel.hpp"
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
         "Normal added-mass coefficient C_a = c_M - 1");
  b.real("tangential_added_mass_coefficient", &SectionRow::tangential_added_mass_coefficient, "-",
         Range::closed(0, 10), "Tangential (axial) added-mass coefficient C_at");
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"start", "Start s"},
      {"end", "End s"},
      {"outer_diameter", "Outer diameter D_out"},
      {"inner_diameter", "Inner diameter D_inn"},
      {"youngs_modulus", "Young's modulus E"},
      {"shear_modulus", "Shear modulus G"},
      {"density", "Wall density"},
      {"normal_drag_coefficient", "Normal drag coefficient D_yz"},
      {"tangential_drag_coefficient", "Tangential drag coefficient D_x"},
      {"added_mass_coefficient", "Added-mass coefficient C_a"},
      {"tangential_added_mass_coefficient", "Tangential added-mass coefficient C_at"},
  });
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
         "Normal added-mass coefficient C_a = c_M - 1 (eq 11), on accelerations across the axis");
  b.real("section.tangential_added_mass_coefficient", &P::tangential_added_mass_coefficient, "-", Range::closed(0, 10),
         "Tangential added-mass coefficient C_at on accelerations along the axis (0: none, as riser and mooring "
         "codes take it; equal to the normal C_a: the paper's isotropic eq 11)");
  b.table("sections", &P::sections, sectionBinder(), 0, 1000, "Stretches with their own section properties");
  bindBuoyancyModules(b);
  b.choice("model.formulation", &P::formulation, {"joint", "absolute"},
           "Coordinates: joint (J, continuity exact) or absolute (A, constraints with Baumgarte stabilisation)");
  b.boolean("model.torsion", &P::torsion, "Torsion on (J3/A3) or off (J2/A2: segments do not spin about their axes)");
  b.real("model.stiffness_damping", &P::stiffness_damping, "s", Range::nonNegative(10.0),
         "Stiffness-proportional spring damping β: damping moments = β·C·(relative angle rates)");
  b.boolean("model.axial_flexibility", &P::axial_flexibility,
            "Axial stretch of the riser (pinned top and bottom): a spring k = 1/Σ(Δ/(E·A_wall)) between the top's "
            "point and the chain, so the top may be held above the riser's length (a fixed-height hang-off)");
  b.real("environment.gravity", &P::gravity, "m/s^2", Range::nonNegative(100.0), "Gravitational acceleration");
  b.real("environment.water_density", &P::water_density, "kg/m^3", Range::nonNegative(1e4), "Sea water density");
  b.real("environment.water_level", &P::water_level, "m", Range::any(), "z of the still-water surface");
  b.real("environment.seabed_level", &P::seabed_level, "m", Range::any(), "z of the sea bed (drawn; with seabed.contact the bed's height at x = y = 0)");
  b.real("environment.internal_fluid_density", &P::internal_fluid_density, "kg/m^3", Range::nonNegative(1e5),
         "Density of the contents");
  b.real("environment.internal_flow_speed", &P::internal_flow_speed, "m/s", Range::closed(-100, 100),
         "Constant flow speed u of the contents along the riser (> 0 from top to bottom; eqs 43-52)");
  b.real("current.speed_surface", &P::current_speed_surface, "m/s", Range::closed(-20, 20), "Current at the surface");
  b.real("current.speed_seabed", &P::current_speed_seabed, "m/s", Range::closed(-20, 20), "Current at the sea bed");
  b.real("current.direction_deg", &P::current_direction_deg, "deg", Range::closed(-360, 360),
         "Current heading from +x towards +y");
  bindCurrentProfile(b);
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
  b.real("top.motion_phase_x_deg", &P::motion_phase_x_deg, "deg", Range::closed(-360, 360), "Phase of the x motion");
  b.real("top.motion_phase_y_deg", &P::motion_phase_y_deg, "deg", Range::closed(-360, 360), "Phase of the y motion");
  b.real("top.motion_phase_z_deg", &P::motion_phase_z_deg, "deg", Range::closed(-360, 360), "Phase of the z motion");
  b.real("top.motion_ramp_time", &P::motion_ramp_time, "s", Range::nonNegative(1e5), "Smooth start of the motion");
  b.choice("top.motion", &P::top_motion, {"harmonic", "table", "vessel"},
           "Top motion: harmonic per axis (amplitudes, period, phases), the time table top_motion_table, or the "
           "vessel section's RAOs in the waves");
  b.table("top_motion_table", &P::top_motion_table, topMotionBinder(), 0, 100000,
          "Top displacement over time (clamped cubic spline; first/last row held outside the table)");
  bindVesselParameters(b);
  b.choice("bottom.condition", &P::bottom_condition, {"pinned", "clamped", "free", "spring"},
           "Bottom end: ball joint at the anchor, clamp, free, or linear spring to the anchor");
  b.real("bottom.x", &P::bottom_x, "m", Range::any(), "Anchor x");
  b.real("bottom.y", &P::bottom_y, "m", Range::any(), "Anchor y");
  b.real("bottom.z", &P::bottom_z, "m", Range::any(), "Anchor z");
  b.real("bottom.spring_stiffness", &P::bottom_spring_stiffness, "N/m", Range::nonNegative(1e12), "Anchor spring");
  b.real("bottom.spring_damping", &P::bottom_spring_damping, "N*s/m", Range::nonNegative(1e12), "Anchor damper");
  b.real("initial.inclination_deg", &P::initial_inclination_deg, "deg", Range::closed(0, 180),
         "Initial direction from the top, measured from straight down (free or spring bottom)");
  b.real("initial.azimuth_deg", &P::initial_azimuth_deg, "deg", Range::closed(-360, 360),
         "Heading of the initial direction from +x towards +y");
  b.boolean("initial.solve_statics", &P::solve_statics, "Start from static equilibrium");
  bindWaveParameters(b);
  bindFatigueParameters(b);
  bindSeabedParameters(b);
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
  b.boolean("output.modes", &P::modes,
            "Natural frequencies, mode shapes and the divergence flow speed about the static state (dense solve up to "
            "n = 199, shift-invert Krylov above; with internal flow only up to n = 199)");
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
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"geometry.length", "Length L"},
      {"geometry.segment_count", "Elements n"},
      {"section.outer_diameter", "Outer diameter D_out"},
      {"section.inner_diameter", "Inner diameter D_inn"},
      {"section.youngs_modulus", "Young's modulus E"},
      {"section.shear_modulus", "Shear modulus G"},
      {"section.density", "Wall density"},
      {"section.normal_drag_coefficient", "Normal drag coefficient D_yz"},
      {"section.tangential_drag_coefficient", "Tangential drag coefficient D_x"},
      {"section.added_mass_coefficient", "Added-mass coefficient C_a"},
      {"section.tangential_added_mass_coefficient", "Tangential added-mass coefficient C_at"},
      {"sections", "section"},
      {"model.stiffness_damping", "Spring damping β"},
      {"environment.gravity", "Gravity g"},
      {"environment.water_density", "Water density"},
      {"environment.water_level", "Water level z"},
      {"environment.internal_fluid_density", "Contents density"},
      {"environment.internal_flow_speed", "Internal flow speed"},
      {"current.speed_surface", "Current at the surface"},
      {"current.speed_seabed", "Current at the sea bed"},
      {"current.direction_deg", "Current heading"},
      {"current.profile", "current profile"},
      {"top.x", "Top x"},
      {"top.y", "Top y"},
      {"top.z", "Top z"},
      {"top.tension", "Top tension"},
      {"top.motion_amplitude_x", "Top motion amplitude x"},
      {"top.motion_amplitude_y", "Top motion amplitude y"},
      {"top.motion_amplitude_z", "Top motion amplitude z"},
      {"top.motion_period", "Top motion period"},
      {"top.motion_phase_x_deg", "Top motion phase x"},
      {"top.motion_phase_y_deg", "Top motion phase y"},
      {"top.motion_phase_z_deg", "Top motion phase z"},
      {"top.motion_ramp_time", "Top motion ramp time"},
      {"environment.seabed_level", "Sea bed z"},
      {"initial.inclination_deg", "Initial inclination"},
      {"initial.azimuth_deg", "Initial azimuth"},
      {"output.frame_count", "Stored frames"},
      {"output.probes", "probe"},
      {"top_motion_table", "top motion table"},
      {"waves.component_count", "Wave components"},
      {"waves.seed", "Wave seed"},
      {"waves.ramp_time", "Wave ramp time"},
      {"waves.phase_deg", "Wave phase"},
      {"vessel.heading_deg", "Vessel heading"},
      {"vessel.offset_x", "Vessel offset x"},
      {"vessel.offset_y", "Vessel offset y"},
      {"vessel.offset_z", "Vessel offset z"},
      {"seabed.slope_deg", "Sea-bed slope"},
      {"seabed.normal_damping", "Sea-bed damping"},
      {"seabed.friction_velocity", "Friction velocity v_s"},
      {"fatigue.start_time", "Fatigue count start"},
      {"fatigue.user_m1", "S-N slope m1"},
      {"fatigue.user_m2", "S-N slope m2"},
      {"bottom.x", "Anchor x"},
      {"bottom.y", "Anchor y"},
      {"bottom.z", "Anchor z"},
      {"bottom.spring_stiffness", "Anchor spring stiffness"},
      {"bottom.spring_damping", "Anchor spring damping"},
      {"solver.end_time", "End time"},
      {"solver.time_step", "Time step h"},
      {"solver.tolerance", "Tolerance"},
      {"waves.height", "Wave height H"},
      {"waves.period", "Wave period T"},
      {"waves.significant_height", "Significant wave height H_s"},
      {"waves.peak_period", "Peak period T_p"},
      {"waves.peak_enhancement", "Peak enhancement γ"},
      {"waves.direction_deg", "Wave direction"},
      {"buoyancy_modules", "buoyancy modules"},
      {"point_loads", "point loads"},
      {"seabed.normal_stiffness", "Sea-bed stiffness"},
      {"seabed.axial_friction_coefficient", "Axial friction coefficient"},
      {"seabed.lateral_friction_coefficient", "Lateral friction coefficient"},
      {"fatigue.stress_concentration_factor", "Stress concentration factor"},
  });
  return b;
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

double initialTopSpeed(const RiserParameters& p) {
  if (p.top_motion != "harmonic" || p.motion_ramp_time > 0 || p.top_condition == "free") return 0.0;
  const double omega = 2 * std::numbers::pi / p.motion_period;
  const double amplitude[3] = {p.motion_amplitude_x, p.motion_amplitude_y,
                               p.top_condition == "tensioner" ? 0.0 : p.motion_amplitude_z};
  const double phase[3] = {p.motion_phase_x_deg, p.motion_phase_y_deg, p.motion_phase_z_deg};
  double squares = 0.0;
  for (int a = 0; a < 3; ++a) {
    // cos(±90°) is 6e-17 in floating point: a start at rest up to round-off counts as at rest.
    const double c = std::cos(radiansFromDegrees(phase[a]));
    if (std::abs(c) > 1e-12) squares += std::pow(amplitude[a] * omega * c, 2);
  }
  return std::sqrt(squares);
}

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
  // A harmonic top motion without a ramp starts the top at full speed while the riser rests: a velocity jump that
  // no state at t = 0 holds (joint coordinates would translate the whole chain with the top, absolute ones jerk
  // the top force). A table needs no such check: its clamped spline starts at zero velocity.
  const double top_speed = initialTopSpeed(p);
  if (top_speed > 0.0 && p.end_time > 0)
    e.push_back({"top.motion_ramp_time", num(p.motion_ramp_time),
                 "the harmonic top motion starts at " + num(top_speed) +
                     " m/s while the riser is at rest (a velocity jump at t = 0): give a smooth start, "
                     "top.motion_ramp_time > 0 (e.g. one period, " + num(p.motion_period) +
                     " s), or phases at which the motion starts at rest (±90°)"});
  for (std::size_t k = 0; k < p.probes.size(); ++k)
    if (p.probes[k].arc_length > p.length)
      e.push_back({"output.probes[" + std::to_string(k) + "].arc_length", num(p.probes[k].arc_length),
                   "must be in [0, " + num(p.length) + "] (geometry.length)"});
  // An inextensible chain cannot reach an anchor farther than its length; exactly L is a singular (taut) system.
  const bool fixed_bottom = p.bottom_condition == "pinned" || p.bottom_condition == "clamped";
  // The mean top: top.x/y/z moved by the static vessel offset.
  const double top_x = p.top_x + p.vessel_offset_x, top_y = p.top_y + p.vessel_offset_y, top_z = p.top_z + p.vessel_offset_z;
  const bool axial = p.axial_flexibility;
  if (axial && (p.top_condition != "pinned" || !fixed_bottom))
    e.push_back({"model.axial_flexibility", "true",
                 "the axial spring needs top.condition = pinned (now \"" + p.top_condition +
                     "\") and bottom.condition pinned or clamped (now \"" + p.bottom_condition + "\")"});
  bool stiff_wall = p.youngs_modulus > 0;
  for (const auto& s : p.sections) stiff_wall = stiff_wall && s.youngs_modulus > 0;
  if (axial && !stiff_wall)
    e.push_back({"section.youngs_modulus", num(p.youngs_modulus),
                 "model.axial_flexibility needs E > 0 in every section (the axial spring is 1/Σ Δ/(E·A))"});
  if (axial && fixed_bottom && p.top_condition == "pinned") {
    // The chain hangs straight from the spring at the start; its stretch must stay elastic and the riser near
    // the vertical through the anchor, where the lumped spring stands for the stretch along the axis.
    const double horizontal = std::hypot(p.bottom_x - top_x, p.bottom_y - top_y);
    const double chord = std::hypot(horizontal, p.bottom_z - top_z);
    if (horizontal > 0.1 * p.length)
      e.push_back({"bottom.x", num(p.bottom_x), "horizontal offset " + num(horizontal) +
                                                    " m from the top must be below 0.1·L = " + num(0.1 * p.length) +
                                                    " with model.axial_flexibility (a near-vertical riser)"});
    if (std::abs(chord - p.length) > 0.01 * p.length)
      e.push_back({"top.z", num(p.top_z), "the top is " + num(chord) + " m from the anchor: with " +
                                              "model.axial_flexibility the stretch must be within ±1 % of L = " +
                                              num(p.length) + " m (elastic strain)"});
  }
  if (!axial && fixed_bottom && (p.top_condition == "pinned" || p.top_condition == "clamped")) {
    const double chord = std::hypot(std::hypot(p.bottom_x - top_x, p.bottom_y - top_y), p.bottom_z - top_z);
    if (chord > 0.999 * p.length)
      e.push_back({"bottom.z", num(p.bottom_z),
                   "anchor is " + num(chord) + " m from the top: must be closer than 0.999·L = " +
                       num(0.999 * p.length) + " m (inextensible segments; use top.condition = tensioner, or model.axial_flexibility = true for a "
                       "fixed-height top)"});
  }
  if (fixed_bottom && p.top_condition == "tensioner") {
    const double horizontal = std::hypot(p.bottom_x - top_x, p.bottom_y - top_y);
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
  checkSeabedParameters(p, e);
  checkBuoyancyModules(p, e);
  checkCurrentProfile(p, e);
  checkVesselParameters(p, e);
  checkFatigueParameters(p, e);
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

namespace {

// Fields renamed when every angle became degrees: {section, old name [rad], new name [deg]}.
struct RenamedAngle {
  const char* section;
  const char* old_name;
  const char* new_name;
};
constexpr RenamedAngle kRenamedAngles[] = {
    {"current", "direction", "direction_deg"},           {"top", "motion_phase_x", "motion_phase_x_deg"},
    {"top", "motion_phase_y", "motion_phase_y_deg"},     {"top", "motion_phase_z", "motion_phase_z_deg"},
    {"initial", "inclination", "inclination_deg"},       {"initial", "azimuth", "azimuth_deg"},
};

// rad → deg, rounded to 12 significant digits (a relative change below 5e-13) so that π/2 reads 90.
double degreesOf(double radians) {
  const double degrees = degreesFromRadians(radians);
  if (degrees == 0.0 || !std::isfinite(degrees)) return degrees;
  const double scale = std::pow(10.0, 11 - static_cast<int>(std::floor(std::log10(std::abs(degrees)))));
  return std::round(degrees * scale) / scale;
}

void upgradeAngles(Json& parameters, std::vector<std::string>& notes) {
  for (const RenamedAngle& r : kRenamedAngles) {
    auto section = parameters.find(r.section);
    if (section == parameters.end() || !section->is_object()) continue;
    auto old = section->find(r.old_name);
    if (old == section->end()) continue;
    const std::string from = std::string(r.section) + "." + r.old_name, to = std::string(r.section) + "." + r.new_name;
    if (section->contains(r.new_name)) {
      notes.push_back(from + " = " + old->dump() + " ignored: " + to + " is given");
    } else if (old->is_number()) {
      const double degrees = degreesOf(old->get<double>());
      (*section)[r.new_name] = degrees;
      notes.push_back(from + " = " + old->dump() + " rad read as " + to + " = " + Json(degrees).dump() +
                      " (angles are degrees in the riser schema; save the scenario to update it)");
    } else {
      (*section)[r.new_name] = *old;  // not a number: left for validation to name under its new path
      notes.push_back(from + " renamed " + to + " (angles are degrees in the riser schema)");
    }
    section->erase(old);
  }
}

// Files from before the tangential added mass had one isotropic C_a (the paper's eq 11): they keep it along the
// axis too, so their results do not change.
void upgradeTangentialAddedMass(Json& parameters, std::vector<std::string>& notes) {
  constexpr const char* kField = "tangential_added_mass_coefficient";
  auto section = parameters.find("section");
  if (section != parameters.end() && section->is_object() && !section->contains(kField) &&
      section->contains("added_mass_coefficient")) {
    (*section)[kField] = (*section)["added_mass_coefficient"];
    notes.push_back(std::string("section.") + kField + " = " + (*section)[kField].dump() +
                    " added, equal to section.added_mass_coefficient: the file predates the tangential added mass "
                    "and keeps its isotropic added mass (the new default is 0; save the scenario to keep it)");
  }
  auto rows = parameters.find("sections");
  if (rows == parameters.end() || !rows->is_array()) return;
  int upgraded = 0;
  for (Json& row : *rows)
    if (row.is_object() && !row.contains(kField) && row.contains("added_mass_coefficient")) {
      row[kField] = row["added_mass_coefficient"];
      ++upgraded;
    }
  if (upgraded > 0)
    notes.push_back(std::to_string(upgraded) + " sections rows given " + kField +
                    " equal to their added_mass_coefficient (isotropic added mass, as the file was written)");
}

void upgradeProbePosition(Json& parameters, std::vector<std::string>& notes) {
  auto output = parameters.find("output");
  if (output == parameters.end() || !output->is_object()) return;
  auto old = output->find("probe_position");
  if (old == output->end()) return;
  if (output->contains("probes")) {
    notes.push_back("output.probe_position = " + old->dump() + " ignored: output.probes is given");
  } else {
    (*output)["probes"] = Json::array({Json{{"arc_length", *old}}});
    notes.push_back("output.probe_position = " + old->dump() + " read as output.probes = [{\"arc_length\": " +
                    old->dump() + "}] (renamed in the riser schema; save the scenario to update it)");
  }
  output->erase(old);
}

}  // namespace

std::vector<std::string> upgradeRiserParameters(Json& parameters) {
  std::vector<std::string> notes;
  if (!parameters.is_object()) return notes;
  // Scenarios written before the stress convergence study existed have no such section: no study.
  if (!parameters.contains("stress_convergence")) {
    parameters["stress_convergence"] = riserBinder().write(RiserParameters{})["stress_convergence"];
    notes.push_back("stress_convergence added without a study (new in the riser schema; save the scenario to keep it)");
  }
  if (!parameters.contains("fatigue")) {
    parameters["fatigue"] = riserBinder().write(RiserParameters{})["fatigue"];
    notes.push_back("fatigue added, off (new in the riser schema; save the scenario to keep it)");
  }
  // Files from before the fatigue sampling interval and the user S–N curve: those fields are added with their
  // defaults (automatic sampling; the user curve is used only with sn_curve = user).
  if (auto f = parameters.find("fatigue"); f != parameters.end() && f->is_object()) {
    const Json defaults = riserBinder().write(RiserParameters{})["fatigue"];
    std::string added;
    for (const char* field : {"sample_interval", "user_log_a1", "user_m1", "user_log_a2", "user_m2",
                              "user_transition_cycles", "user_thickness_exponent", "user_reference_thickness"})
      if (!f->contains(field)) {
        (*f)[field] = defaults[field];
        added += std::string(added.empty() ? "" : ", ") + "fatigue." + field;
      }
    if (!added.empty())
      notes.push_back(added + " added with defaults (new in the riser schema: automatic fatigue sampling, the user "
                              "S-N curve; save the scenario to keep them)");
  }
  if (!parameters.contains("waves")) {
    parameters["waves"] = riserBinder().write(RiserParameters{})["waves"];
    notes.push_back("waves added as none (new in the riser schema; save the scenario to keep it)");
  }
  if (!parameters.contains("seabed")) {
    parameters["seabed"] = riserBinder().write(RiserParameters{})["seabed"];
    notes.push_back("seabed added without contact (new in the riser schema; save the scenario to keep it)");
  }
  if (!parameters.contains("buoyancy_modules")) {
    parameters["buoyancy_modules"] = Json::array();
    notes.push_back("buoyancy_modules added, empty (new in the riser schema; save the scenario to keep it)");
  }
  upgradeCurrentProfile(parameters, notes);
  upgradeVesselParameters(parameters, notes);
  upgradeProbePosition(parameters, notes);
  upgradeAngles(parameters, notes);
  upgradeTangentialAddedMass(parameters, notes);
  // Files from before the modes switch always computed the modes.
  auto output = parameters.find("output");
  if (output != parameters.end() && output->is_object() && !output->contains("modes")) {
    (*output)["modes"] = true;
    notes.push_back("output.modes = true added (new in the riser schema: natural frequencies and modes, as before)");
  }
  // Files from before the axial spring have inextensible risers.
  auto model = parameters.find("model");
  if (model != parameters.end() && model->is_object() && !model->contains("axial_flexibility")) {
    (*model)["axial_flexibility"] = false;
    notes.push_back("model.axial_flexibility = false added (new in the riser schema: inextensible, as before)");
  }
  return notes;
}

}  // namespace maris::riser
