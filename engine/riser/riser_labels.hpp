// What people read for the riser's result columns: one label per column name, with symbols (σ_b, τ_t, ω₁),
// written beside the tables that make them (riser_results, riser_envelope, riser_fatigue, the sweeps).
#pragma once

#include <string>

namespace maris::riser {

// The label of column `name`: "Probe 1 dx", "σ_b at probe 2", "Top force F_z", "ω₁ reference", "σ_b at t = 12.5 s";
// a name it does not know is made readable (core readableName).
std::string riserColumnLabel(const std::string& name);

}  // namespace maris::riser
