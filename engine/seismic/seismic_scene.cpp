// Registry entry of the seismic scene.
#include "core/scene.hpp"
#include "seismic/seismic_parameters.hpp"
#include "seismic/seismic_plausibility.hpp"
#include "seismic/seismic_solve.hpp"

namespace maris {

SceneDefinition makeSeismicScene() {
  using seismic::SeismicParameters;
  SceneDefinition scene = makeScene<SeismicParameters>(
      "seismic", "Reef–seawater seismic response (2D)",
      "2D plane-strain reef on an elastic seabed with the surrounding seawater under obliquely incident P or SV "
      "plane waves (Bao, Liu et al., Ocean Engineering ~2020): analytic free field of a half-space under a water "
      "layer, explicit finite elements with viscous-spring and fluid radiation boundaries and boundary-substructure "
      "input; amplification along the reef flat, spectral ratios, effect of the water. The default reef is a "
      "placeholder (the paper's Table 1 is not available).",
      seismic::seismicBinder(), seismic::checkSeismicParameters, seismic::solveSeismic);
  setWorkEstimate<SeismicParameters>(scene, seismic::seismicBinder(), seismic::estimateSeismicWork);
  setPlausibility<SeismicParameters>(scene, seismic::seismicBinder(), seismic::seismicPlausibility);
  // The plot list's headings (the names are those of seismic_fe_report.cpp, seismic_spectral_map.cpp,
  // seismic_free_field_report.cpp and seismic_modal_report.cpp; ui.labels checks that every plot of every built-in
  // scenario is in exactly one group and every name here names a plot of one). The angle sweep, which no built-in
  // scenario makes, keeps the heading of its table.
  scene.plot_groups = {
      {"Amplification along the flat",
       {"amplification", "spectral_ratio_along_flat", "spectral_ratio_lines_x", "spectral_ratio_lines_y"}},
      {"At the stations on the flat: spectra and histories", {"spectral_ratio", "station_histories"}},
      {"Free field: the layered site without the reef", {"free_field_transfer", "free_field_histories"}},
      {"Checks: FE against the free field, modal masses", {"verification", "modes"}},
  };
  return scene;
}

}  // namespace maris
