#include "tether/tether_results.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/text_format.hpp"

namespace maris::tether {

namespace {

constexpr double kToDegrees = 180.0 / std::numbers::pi;

template <class F>
std::vector<double> column(const SimulationOutput& sim, F f) {
  std::vector<double> v;
  v.reserve(sim.ticks.size());
  for (const auto& t : sim.ticks) v.push_back(f(t));
  return v;
}

Table featureTable(const TetherParameters& p, const SimulationOutput& sim) {
  Table t{"features", "Features, shape and errors vs time", {}};
  t.add("time", "s", column(sim, [](const TickRecord& r) { return r.time; }), "Time");
  t.add("a", "-", column(sim, [](const TickRecord& r) { return r.features.a; }), "Feature a");
  t.add("b", "-", column(sim, [](const TickRecord& r) { return r.features.b; }), "Feature b");
  t.add("d", "-", column(sim, [](const TickRecord& r) { return r.features.d; }), "Feature d");
  t.add("b1", "-", column(sim, [](const TickRecord& r) { return r.features.b1; }), "Feature b₁");
  t.add("a_target", "-", std::vector<double>(sim.ticks.size(), p.target_a), "a*");
  t.add("b_target", "-", std::vector<double>(sim.ticks.size(), p.target_b), "b*");
  t.add("d_target", "-", std::vector<double>(sim.ticks.size(), p.target_d), "d*");
  t.add("b1_target", "-", std::vector<double>(sim.ticks.size(), p.target_b1), "b₁*");
  t.add("a_measured", "-", column(sim, [](const TickRecord& r) { return r.measured.a; }), "a measured");
  t.add("b_measured", "-", column(sim, [](const TickRecord& r) { return r.measured.b; }), "b measured");
  t.add("vision_held", "-", column(sim, [](const TickRecord& r) { return r.vision_held ? 1.0 : 0.0; }), "Vision held (1 = yes)");
  t.add("vision_fit_converged", "-", column(sim, [](const TickRecord& r) { return r.vision_converged ? 1.0 : 0.0; }), "Vision fit converged (1 = yes)");
  t.add("visible_points", "-", column(sim, [](const TickRecord& r) { return double(r.visible_points); }), "Visible points");
  t.add("error_norm", "-", column(sim, [](const TickRecord& r) { return std::max(r.error.norm(), 1e-16); }), "|s − s*|");
  t.add("sag", "m", column(sim, [](const TickRecord& r) { return r.sag; }), "Sag H");
  t.add("rise", "m", column(sim, [](const TickRecord& r) { return r.rise; }), "Rise ΔH");
  t.add("span", "m", column(sim, [](const TickRecord& r) { return r.span; }), "Span");
  t.add("catenary_constant", "1/m", column(sim, [](const TickRecord& r) { return r.constant; }), "Catenary constant C");
  t.add("alpha2_deg", "deg", column(sim, [](const TickRecord& r) { return r.follower_angle * kToDegrees; }), "α₂ follower");
  t.add("alpha1_deg", "deg", column(sim, [](const TickRecord& r) { return r.leader_angle * kToDegrees; }), "α₁ leader");
  t.add("fits_model", "-", column(sim, [](const TickRecord& r) {
          return r.regime == CatenaryRegime::Regular || r.regime == CatenaryRegime::NearlyTaut ? 1.0 : 0.0; }), "Fits the model (1 = yes)");
  t.add("held", "-", column(sim, [](const TickRecord& r) { return r.held ? 1.0 : 0.0; }), "Command held (1 = yes)");
  return t;
}

Table commandTable(const SimulationOutput& sim) {
  Table t{"commands", "Follower commands, leader twist and poses vs time", {}};
  t.add("time", "s", column(sim, [](const TickRecord& r) { return r.time; }), "Time");
  const char* names[] = {"nu_x", "nu_y", "nu_z"};
  const char* symbols[] = {"ν_x", "ν_y", "ν_z"};
  for (int i = 0; i < 3; ++i)
    t.add(names[i], "m/s", column(sim, [i](const TickRecord& r) { return r.command[i]; }),
          std::string("Follower ") + symbols[i]);
  t.add("omega_z_deg", "deg/s", column(sim, [](const TickRecord& r) { return r.command[3] * kToDegrees; }), "Follower ω_z");
  for (int i = 0; i < 3; ++i)
    t.add(std::string("leader_") + names[i], "m/s", column(sim, [i](const TickRecord& r) { return r.leader_twist[i]; }),
          std::string("Leader ") + symbols[i]);
  t.add("leader_omega_z_deg", "deg/s", column(sim, [](const TickRecord& r) { return r.leader_twist[3] * kToDegrees; }), "Leader ω_z");
  t.add("saturated", "-", column(sim, [](const TickRecord& r) { return r.saturated ? 1.0 : 0.0; }), "Saturated (1 = yes)");
  t.add("smallest_singular_value", "-", column(sim, [](const TickRecord& r) { return r.smallest_singular_value; }), "Smallest singular value");
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i)
    t.add(std::string("follower_") + axes[i], "m", column(sim, [i](const TickRecord& r) { return r.follower.position[i]; }),
          std::string("Follower ") + axes[i]);
  t.add("follower_yaw_deg", "deg", column(sim, [](const TickRecord& r) { return r.follower.yaw * kToDegrees; }), "Follower yaw");
  for (int i = 0; i < 3; ++i)
    t.add(std::string("leader_") + axes[i], "m", column(sim, [i](const TickRecord& r) { return r.leader.position[i]; }),
          std::string("Leader ") + axes[i]);
  t.add("leader_yaw_deg", "deg", column(sim, [](const TickRecord& r) { return r.leader.yaw * kToDegrees; }), "Leader yaw");
  return t;
}

Table eigenvalueTable(const TetherParameters& p, const SimulationOutput& sim) {
  Table t{"closed_loop_eigenvalues", "Eigenvalues of L diag(lambda_p) Lhat+ vs time (0 while held)", {}};
  t.add("time", "s", column(sim, [](const TickRecord& r) { return r.time; }), "Time");
  const int n = p.law == "both_cameras" ? 4 : 3;
  for (int i = 0; i < n; ++i) {
    t.add("real_" + std::to_string(i + 1), "1/s", column(sim, [i](const TickRecord& r) {
            return r.eigenvalues.size() > i ? r.eigenvalues[i].real() : 0.0; }), "Re λ" + std::to_string(i + 1));
    t.add("imag_" + std::to_string(i + 1), "1/s", column(sim, [i](const TickRecord& r) {
            return r.eigenvalues.size() > i ? r.eigenvalues[i].imag() : 0.0; }), "Im λ" + std::to_string(i + 1));
  }
  return t;
}

Table cableTable(const SimulationOutput& sim) {
  Table t{"cable", "Lumped-mass cable against the quasi-static catenary", {}};
  t.add("time", "s", column(sim, [](const TickRecord& r) { return r.time; }), "Time");
  t.add("max_deviation", "m", column(sim, [](const TickRecord& r) { return std::max(r.cable_deviation, 1e-12); }), "Cable–catenary distance");
  t.add("cable_sag", "m", column(sim, [](const TickRecord& r) { return r.cable_sag; }), "Cable sag");
  t.add("catenary_sag", "m", column(sim, [](const TickRecord& r) {
          return r.regime == CatenaryRegime::VertexOutsideSpan ? 0.0 : r.sag; }), "Catenary sag");
  t.add("kinetic_energy", "J", column(sim, [](const TickRecord& r) { return r.cable_kinetic_energy; }), "Cable kinetic energy");
  t.add("projection_iterations", "-", column(sim, [](const TickRecord& r) { return double(r.cable_iterations); }), "Projection iterations");
  return t;
}

// Final tether profile: height above P2 along the arc for the catenary and the cable.
Table profileTable(const TetherParameters& p, const SimulationOutput& sim) {
  Table t{"final_profile", "Final tether height along the arc: catenary and lumped-mass cable", {}};
  const Snapshot& last = sim.frames.back();
  std::vector<double> arc, catenary_z, cable_z;
  const int n = p.cable_enabled ? static_cast<int>(last.cable.size()) - 1 : 100;
  for (int i = 0; i <= n; ++i) {
    const double s = p.length * i / n;
    arc.push_back(s);
    catenary_z.push_back(tetherPointAtArcLength(last.tether, s).z() - last.tether.follower_point.z());
    if (p.cable_enabled) cable_z.push_back(last.cable[i].z() - last.tether.follower_point.z());
  }
  t.add("arc_length", "m", arc, "Arc length s");
  t.add("catenary_height", "m", catenary_z, "Catenary z");
  if (p.cable_enabled) t.add("cable_height", "m", cable_z, "Cable z");
  return t;
}

// Minimum real part of the closed-loop eigenvalues at the target for relative errors of a and b in +-40 %
// (paper §6, Fig. 8 with per-axis gains).
Table stabilityTable(const TetherParameters& p) {
  Table t{"stability_map", "Closed-loop eigenvalues at the target under model errors of a and b", {}};
  std::vector<double> ea, eb, min_real, max_imag;
  const TetherRig rig = rigOf(p);
  const ServoSettings settings = servoSettingsOf(p);
  const Features truth{p.target_a, p.target_b, p.target_d, p.target_b1};
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      const Features model{truth.a * (1 + 0.1 * i), truth.b * (1 + 0.1 * j), truth.d, truth.b1};
      if (!featureInfeasibility(rig, model).empty()) continue;
      const Eigen::VectorXcd values = closedLoopEigenvalues(rig, settings, truth, model);
      ea.push_back(0.1 * i);
      eb.push_back(0.1 * j);
      min_real.push_back(values.real().minCoeff());
      max_imag.push_back(values.imag().cwiseAbs().maxCoeff());
    }
  t.add("error_a", "-", ea, "Error in a");
  t.add("error_b", "-", eb, "Error in b");
  t.add("min_real_part", "1/s", min_real, "min Re λ");
  t.add("max_imag_part", "1/s", max_imag, "max |Im λ|");
  return t;
}

// Most tether plots are histories: x = time.
PlotSpec plot(std::string name, std::string title, std::string table, std::vector<std::string> y, bool log_y = false,
              std::string x = "time") {
  return makePlot(std::move(name), std::move(title), std::move(table), std::move(x), std::move(y), log_y);
}

void addPlots(const TetherParameters& p, Results& r) {
  const bool four = p.law == "both_cameras";
  std::vector<std::string> features{"a", "b", "d", "a_target", "b_target", "d_target"};
  if (four) features.insert(features.end(), {"b1", "b1_target"});
  r.plots.push_back(plot("features", "Features and targets", "features", features));
  if (p.vision_enabled)
    r.plots.push_back(plot("estimates", "Estimated vs true a and b", "features", {"a", "a_measured", "b", "b_measured"}));
  r.plots.push_back(plot("error_norm", "Feature error norm", "features", {"error_norm"}, true));
  r.plots.push_back(plot("shape", "Catenary shape: sag, rise, span", "features", {"sag", "rise", "span"}));
  r.plots.push_back(plot("angles", "Tether-plane angles", "features", {"alpha2_deg", "alpha1_deg"}));
  r.plots.push_back(plot("linear_commands", "Follower linear velocity commands", "commands", {"nu_x", "nu_y", "nu_z"}));
  r.plots.push_back(plot("yaw_command", "Follower yaw-rate command", "commands", {"omega_z_deg"}));
  std::vector<std::string> reals;
  for (int i = 1; i <= (four ? 4 : 3); ++i) reals.push_back("real_" + std::to_string(i));
  r.plots.push_back(plot("eigenvalues", "Closed-loop eigenvalues (real parts)", "closed_loop_eigenvalues", reals));
  if (p.cable_enabled) {
    r.plots.push_back(plot("cable_deviation", "Cable deviation from the catenary", "cable", {"max_deviation"}, true));
    r.plots.push_back(plot("cable_sag", "Sag: cable vs catenary", "cable", {"cable_sag", "catenary_sag"}));
    r.plots.push_back(plot("final_profile", "Final tether profile", "final_profile", {"catenary_height", "cable_height"}, false,
                         "arc_length"));
  }
}

}  // namespace

View3D buildTetherView(const TetherParameters& p, const SimulationOutput& sim);

Results buildTetherResults(const TetherParameters& p, const SimulationOutput& sim, RunContext& context) {
  Results r;
  r.tables.push_back(featureTable(p, sim));
  r.tables.push_back(commandTable(sim));
  r.tables.push_back(eigenvalueTable(p, sim));
  if (p.cable_enabled) r.tables.push_back(cableTable(sim));
  r.tables.push_back(profileTable(p, sim));
  r.tables.push_back(stabilityTable(p));
  addPlots(p, r);
  r.view = buildTetherView(p, sim);

  // Key scalars.
  const auto& first = sim.ticks.front();
  const auto& last = sim.ticks.back();
  const double e0 = first.error.norm();
  double peak = 0.0;
  for (const auto& t : sim.ticks) peak = std::max(peak, t.error.norm());
  double settling = -1.0, max_speed = 0.0, max_yaw = 0.0, min_real = 1e300, max_dev = 0.0;
  long held = 0;
  for (const auto& t : sim.ticks) {
    if (t.error.norm() > 0.02 * peak) settling = -1.0;
    else if (settling < 0.0) settling = t.time;
    max_speed = std::max(max_speed, t.command.head<3>().cwiseAbs().maxCoeff());
    max_yaw = std::max(max_yaw, std::abs(t.command[3]));
    if (t.eigenvalues.size()) min_real = std::min(min_real, t.eigenvalues.real().minCoeff());
    max_dev = std::max(max_dev, t.cable_deviation);
    held += t.held ? 1 : 0;
  }
  r.addScalar("initial_error_norm", e0, "-", "Feature error |s - s*| at t = 0", "Initial |e|");
  r.addScalar("peak_error_norm", peak, "-", "Largest feature error over the run (after pushes)", "Peak |e|");
  r.addScalar("final_error_norm", last.error.norm(), "-", "Feature error at the end", "Final |e|");
  if (settling < 0.0) {
    context.warn("the feature error did not stay below 2 % of its peak; the settling time shown is the duration");
    settling = last.time;
  }
  r.addScalar("settling_time", settling, "s", "Time after which |e| stays below 2 % of its peak over the run", "Settling time");
  r.addScalar("final_sag", last.sag, "m", "Sag H at the follower attachment at the end", "Final sag H");
  r.addScalar("final_rise", last.rise, "m", "Rise dH = z(P1) - z(P2) at the end", "Final rise ΔH");
  r.addScalar("final_span", last.span, "m", "Horizontal span at the end", "Final span");
  r.addScalar("final_follower_angle", last.follower_angle * kToDegrees, "deg", "alpha2 at the end", "Final α₂");
  r.addScalar("max_linear_command", max_speed, "m/s", "Largest linear velocity command component", "max |ν|");
  r.addScalar("max_yaw_command", max_yaw * kToDegrees, "deg/s", "Largest yaw-rate command", "max |ω_z|");
  r.addScalar("min_eigenvalue_real_part", min_real < 1e300 ? min_real : 0.0, "1/s",
              "Smallest real part of the closed-loop eigenvalues over the run (> 0: locally stable)", "min Re λ");
  r.addScalar("held_ticks", static_cast<double>(held), "-", "Ticks with the command held (singular or invalid shape)", "Held ticks");
  const double w = wetWeightPerLength(p);
  r.addScalar("wet_weight_per_length", w, "N/m", "Tether weight minus buoyancy per length", "Wet weight w");
  if (last.constant > 0.0)
    r.addScalar("final_horizontal_tension", w / last.constant, "N", "w/C at the end (catenary statics)", "Final horizontal tension H");
  if (p.cable_enabled) {
    r.addScalar("max_cable_deviation", max_dev, "m", "Largest distance of a cable node from the catenary", "max cable–catenary distance");
    r.addScalar("final_cable_deviation", last.cable_deviation, "m", "Cable-catenary distance at the end", "Final cable–catenary distance");
  }

  r.stats.steps = static_cast<long>(sim.ticks.size()) - 1;
  r.stats.rhs_evaluations = sim.cable_steps;
  r.stats.error_estimate = sim.worst_constraint_error;
  r.stats.error_unit = "relative link length² error of the cable";
  r.stats.method = "kinematic robots at " + numberText(p.control_rate) + " Hz (exact pose update)" +
                   (p.cable_enabled ? "; lumped-mass cable, symplectic Euler + link projection (SHAKE, then Newton), " +
                                          std::to_string(p.cable_substeps) + " sub-steps per tick"
                                    : std::string());
  return r;
}

}  // namespace maris::tether
