// Buoyancy modules along the riser (the `buoyancy_modules` table): stretches [start, end) of arc length where
// clamped-on modules of a larger equivalent diameter give buoyancy, drag and added mass in place of the pipe's outer
// diameter and add their own mass; stiffness and stresses stay the pipe's. A segment partly covered takes the
// covered fraction f of its length: per-length mass, buoyancy area, drag and added mass are the length-weighted
// averages of modules and bare pipe, so the riser's total buoyancy and mass do not depend on where the module ends
// fall between joints.
#pragma once

#include <vector>

#include "core/errors.hpp"
#include "core/schema_binder.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::riser {

// Sums over the modules overlapping [s0, s1), each weighted by its share of that length.
struct ModuleShare {
  double fraction = 0.0;         // [-] Σ f_k
  double mass_per_length = 0.0;  // [kg/m] Σ f_k m_k
  double area = 0.0;             // [m²] Σ f_k A_k (A_k = π D_k²/4)
  double drag_width = 0.0;       // [m] Σ f_k D_k C_dn,k
  double added_mass_area = 0.0;  // [m²] Σ f_k C_a,k A_k
};
ModuleShare buoyancyModuleShare(const RiserParameters& p, double s0, double s1);

// The table's binder (riserBinder) and its checks (checkRiserParameters): rows inside [0, L], start < end, not
// overlapping, module diameter not below the pipe's outer diameter there.
void bindBuoyancyModules(SchemaBinder<RiserParameters>& b);
void checkBuoyancyModules(const RiserParameters& p, std::vector<FieldError>& errors);

}  // namespace maris::riser
