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
  return scene;
}

}  // namespace maris
