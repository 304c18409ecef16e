// Modal table of the reef (paper Table 2): the lowest natural modes of the reef + seabed on the
// scene's own mesh, with the water coupled when model.include_water (fluid–solid modes, as the
// paper's FLUID80 model) or dry otherwise, and the diagnostics that tell a global mode (large
// effective mass) from a partial mode of the upper layers (motion concentrated in layer 1) and a
// water mode (water_share near 1).
#include <algorithm>
#include <string>

#include "seismic/fe_mesh.hpp"
#include "seismic/fe_modes.hpp"
#include "seismic/seismic_solve.hpp"
#include "core/text_format.hpp"

namespace maris::seismic {

void addModalResults(const SeismicParameters& p, Results& results, RunContext& ctx) {
  FeModel model = buildFeModel(buildMesh(p, p.include_water));
  // The sparse factorisation of a very fine mesh needs gigabytes: use the coarse companion mesh then.
  constexpr std::size_t kMaxModalCells = 150000;
  if (model.solid_cells.size() > kMaxModalCells) {
    model = buildFeModel(buildMesh(p, p.include_water, true));
    ctx.warn("modal analysis on the coarse mesh (Δ = " + numberText(model.mesh.delta) + " m): the main mesh has over " +
             std::to_string(kMaxModalCells) + " solid cells");
  }
  const bool wet = p.include_water && p.water_depth > 0.0;
  const bool fixed = p.modal_base == "fixed";
  const ModalResult r =
      wet ? computeCoupledModes(model, p.mode_count, fixed, ctx) : computeSolidModes(model, p.mode_count, fixed, ctx);
  if (r.modes.empty()) return;

  Table t{"modes", wet ? "Fluid–solid natural modes of the reef, seabed and water"
                       : "Natural modes of the solid reef and seabed (no water)", {}};
  std::vector<double> index, f, horizontal, reef, top, mx, my, residual, water;
  double worst = 0.0;
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const SolidMode& m = r.modes[k];
    index.push_back(static_cast<double>(k + 1));
    f.push_back(m.frequency);
    horizontal.push_back(m.horizontal_share);
    reef.push_back(m.reef_share);
    top.push_back(m.top_layer_share);
    mx.push_back(m.mass_ratio_x);
    my.push_back(m.mass_ratio_y);
    residual.push_back(m.residual);
    water.push_back(m.water_share);
    worst = std::max(worst, m.residual);
  }
  t.add("mode", "-", index, "Mode");
  t.add("frequency", "Hz", f, "Frequency f");
  t.add("horizontal_share", "-", horizontal, "Horizontal share");
  t.add("reef_share", "-", reef, "Reef share");
  t.add("top_layer_share", "-", top, "Top-layer share");
  t.add("mass_ratio_x", "-", mx, "Mass ratio x");
  t.add("mass_ratio_y", "-", my, "Mass ratio y");
  t.add("residual", "-", residual, "Residual");
  if (wet) t.add("water_share", "-", water, "Water share");
  results.tables.push_back(std::move(t));
  results.plots.push_back({"modes", "Modal effective masses", "modes", "frequency", {"mass_ratio_x", "mass_ratio_y"},
                           false, false, "", {}});

  // Global modes: the largest effective mass in x and in y among the computed modes.
  const auto gx = std::max_element(mx.begin(), mx.end()) - mx.begin();
  const auto gy = std::max_element(my.begin(), my.end()) - my.begin();
  results.addScalar("mode_1_frequency", f[0], "Hz", "Lowest natural frequency of the solid reef and seabed", "f₁");
  results.addScalar("global_horizontal_mode_frequency", f[gx], "Hz",
                    "Computed mode with the largest horizontal effective mass (paper: 0.42 Hz for its reef)", "f of the global horizontal mode");
  results.addScalar("global_vertical_mode_frequency", f[gy], "Hz",
                    "Computed mode with the largest vertical effective mass (paper: 0.51 Hz for its reef)", "f of the global vertical mode");
  results.addScalar("modal_residual_max", worst, "-", "Largest ‖Kx − ω²Mx‖/‖Kx‖ of the reported modes", "max modal residual");
}

}  // namespace maris::seismic
