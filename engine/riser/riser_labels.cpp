#include "riser/riser_labels.hpp"

#include <map>

#include "core/results.hpp"

namespace maris::riser {

namespace {

const std::map<std::string, std::string>& fixedLabels() {
  static const std::map<std::string, std::string> labels = {
      {"time", "Time"}, {"node", "Node"}, {"mode", "Mode"}, {"probe", "Probe"}, {"arc_length", "Arc length s"},
      {"x", "x"}, {"y", "y"}, {"z", "z"}, {"dx", "dx"}, {"dy", "dy"}, {"dz", "dz"}, {"twist", "Twist"},
      {"top_x", "Top x"}, {"top_y", "Top y"}, {"top_z", "Top z"},
      {"end_x", "Bottom end x"}, {"end_y", "Bottom end y"}, {"end_z", "Bottom end z"},
      {"top_force_x", "Top force F_x"}, {"top_force_y", "Top force F_y"}, {"top_force_z", "Top force F_z"},
      {"bottom_force_x", "Bottom force F_x"}, {"bottom_force_y", "Bottom force F_y"},
      {"bottom_force_z", "Bottom force F_z"},
      {"kinetic_energy", "Kinetic energy"}, {"spring_energy", "Spring energy"}, {"gravity_energy", "Gravity energy"},
      {"total_energy", "Total energy"}, {"work_drag", "Work of drag"}, {"work_damping", "Work of damping"},
      {"work_boundary", "Work at the ends"}, {"work_flow", "Work of the flow"},
      {"energy_balance_error", "Energy balance error"}, {"constraint_drift", "Constraint drift |Φ|"},
      {"wave_elevation", "Wave elevation η"},
      {"displacement", "Displacement"}, {"tension", "Tension T"}, {"bending_stress", "Bending stress σ_b"},
      {"stress_xy", "σ_b in the x-y plane"}, {"stress_xz", "σ_b in the x-z plane"},
      {"torsional_stress", "Torsional stress τ_t"}, {"curvature", "Curvature κ"},
      {"displacement_amplitude", "Displacement amplitude"}, {"curvature_amplitude", "Curvature amplitude κ_a"},
      {"damage", "Fatigue damage D"}, {"damage_per_year", "Damage per year"}, {"life", "Fatigue life"},
      {"hot_spot_angle", "Hot-spot angle"},
      {"joint_above", "Joint above"}, {"weight_below", "Weight of the joint below"},
      {"max_displacement", "max displacement"}, {"max_bending_stress", "max σ_b"},
      {"angular_frequency", "ω"}, {"frequency", "f"}, {"period", "Period T"}, {"torsion_share", "Torsion share"},
      {"pretension_ratio", "Pretension ratio i_T"}, {"top_tension", "Top tension T_top"},
      {"omega_1", "ω₁"}, {"omega_2", "ω₂"}, {"omega_1_reference", "ω₁ reference"}, {"omega_2_reference", "ω₂ reference"},
      {"omega_1_eq66", "ω₁ closed form (eq. 66)"}, {"omega_2_eq66", "ω₂ closed form (eq. 66)"},
      {"difference_1", "Relative difference of ω₁"}, {"difference_2", "Relative difference of ω₂"},
      {"error_1", "Relative error of ω₁"}, {"error_2", "Relative error of ω₂"},
      {"segment_count", "Segments n"}, {"integrator_error_estimate", "Integrator error estimate"},
      {"steps", "Steps"}, {"wall_time", "Wall time"},
      {"max_bending_stress_difference", "Relative difference of max σ_b"},
  };
  return labels;
}

// Probe quantities: "dx" of probe k as "Probe k dx".
const std::map<std::string, std::string>& probeQuantities() {
  static const std::map<std::string, std::string> quantities = {
      {"dx", "dx"}, {"dy", "dy"}, {"dz", "dz"}, {"bending_stress", "σ_b"}, {"torsional_stress", "τ_t"},
      {"displacement", "displacement"}, {"max_displacement", "max displacement"}};
  return quantities;
}

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }
bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::string riserColumnLabel(const std::string& name) {
  if (const auto it = fixedLabels().find(name); it != fixedLabels().end()) return it->second;
  // probe_dx (probe 1), probe3_dx (probe 3): see probeColumn in riser_results.cpp.
  if (startsWith(name, "probe")) {
    const std::size_t underscore = name.find('_');
    if (underscore != std::string::npos) {
      const std::string number = underscore == 5 ? "1" : name.substr(5, underscore - 5);
      if (const auto q = probeQuantities().find(name.substr(underscore + 1)); q != probeQuantities().end())
        return "Probe " + number + " " + q->second;
    }
  }
  // bending_stress_t12.5 and bending_stress_t12.5_difference: the stress at a chosen time.
  if (startsWith(name, "bending_stress_t")) {
    std::string time = name.substr(16);
    const bool difference = endsWith(time, "_difference");
    if (difference) time.resize(time.size() - 11);
    for (char& c : time)
      if (c == '_') c = '.';  // formatTime writes 12.5 as 12_5
    return (difference ? "Relative difference of σ_b at t = " : "σ_b at t = ") + time + " s";
  }
  return readableName(name);
}

}  // namespace maris::riser
