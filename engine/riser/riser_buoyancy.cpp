// Buoyancy modules (contract in riser/riser_buoyancy.hpp).
#include "riser/riser_buoyancy.hpp"

#include <algorithm>
#include <numbers>
#include <string>

#include "core/text_format.hpp"

namespace maris::riser {
namespace {

SchemaBinder<BuoyancyModuleRow> moduleBinder() {
  using R = BuoyancyModuleRow;
  SchemaBinder<R> b;
  b.real("start", &R::start, "m", Range::nonNegative(), "Arc length from the top where the modules begin");
  b.real("end", &R::end, "m", Range::positive(), "Arc length from the top where they end");
  b.real("outer_diameter", &R::outer_diameter, "m", Range::positive(20.0),
         "Equivalent outer diameter of the modules (buoyancy, drag, added mass, sea-bed contact)");
  b.real("mass_per_length", &R::mass_per_length, "kg/m", Range::positive(1e5),
         "Mass of the modules in air per length of riser");
  b.real("normal_drag_coefficient", &R::normal_drag_coefficient, "-", Range::closed(0, 10),
         "Normal drag coefficient on the modules' diameter");
  b.real("added_mass_coefficient", &R::added_mass_coefficient, "-", Range::closed(0, 10),
         "Normal added-mass coefficient on the modules' diameter");
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"start", "Start s"},
      {"end", "End s"},
      {"outer_diameter", "Module diameter"},
      {"mass_per_length", "Module mass per length"},
  });
  return b;
}

}  // namespace

ModuleShare buoyancyModuleShare(const RiserParameters& p, double s0, double s1) {
  ModuleShare share;
  for (const auto& row : p.buoyancy_modules) {
    const double overlap = std::min(s1, row.end) - std::max(s0, row.start);
    if (overlap <= 0 || s1 <= s0) continue;
    const double f = overlap / (s1 - s0), area = std::numbers::pi / 4 * row.outer_diameter * row.outer_diameter;
    share.fraction += f;
    share.mass_per_length += f * row.mass_per_length;
    share.area += f * area;
    share.drag_width += f * row.outer_diameter * row.normal_drag_coefficient;
    share.added_mass_area += f * row.added_mass_coefficient * area;
  }
  return share;
}

void bindBuoyancyModules(SchemaBinder<RiserParameters>& b) {
  b.table("buoyancy_modules", &RiserParameters::buoyancy_modules, moduleBinder(), 0, 100,
          "Buoyancy modules over arc-length ranges (lazy-wave shapes): their diameter replaces the pipe's for "
          "buoyancy, drag and added mass, their mass is added; stiffness stays the pipe's");
}

void checkBuoyancyModules(const RiserParameters& p, std::vector<FieldError>& e) {
  std::vector<std::size_t> order(p.buoyancy_modules.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    order[k] = k;
    const auto& r = p.buoyancy_modules[k];
    const std::string at = "buoyancy_modules[" + std::to_string(k) + "]";
    if (r.end <= r.start) e.push_back({at + ".end", formatText("%g", r.end), "must be greater than start = " + formatText("%g", r.start)});
    if (r.end > p.length)
      e.push_back({at + ".end", formatText("%g", r.end), "must be at most geometry.length = " + formatText("%g", p.length)});
    // The pipe's own outer diameter where the modules sit (sections rows win over the uniform section).
    double pipe = p.outer_diameter;
    for (const auto& s : p.sections)
      if (0.5 * (r.start + r.end) >= s.start && 0.5 * (r.start + r.end) < s.end) pipe = s.outer_diameter;
    if (r.outer_diameter < pipe)
      e.push_back({at + ".outer_diameter", formatText("%g", r.outer_diameter),
                   "must not be below the pipe's outer diameter " + formatText("%g", pipe) + " m there"});
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return p.buoyancy_modules[a].start < p.buoyancy_modules[b].start; });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const auto& before = p.buoyancy_modules[order[k - 1]];
    const auto& row = p.buoyancy_modules[order[k]];
    if (row.start < before.end)
      e.push_back({"buoyancy_modules[" + std::to_string(order[k]) + "].start", formatText("%g", row.start),
                   "overlaps buoyancy_modules[" + std::to_string(order[k - 1]) + "], which ends at " + formatText("%g", before.end)});
  }
}

}  // namespace maris::riser
