// Registry entry of the tether scene.
#include "core/scene.hpp"
#include "tether/tether_parameters.hpp"
#include "tether/tether_results.hpp"

namespace maris {

SceneDefinition makeTetherScene() {
  using tether::TetherParameters;
  return makeScene<TetherParameters>(
      "tether", "Tether shape control between two ROVs",
      "A follower ROV keeps the passive, negatively buoyant tether to a leader ROV at a desired catenary shape "
      "(sag, tether-plane angle, height offset) by visual servoing with the analytic catenary interaction matrix "
      "(Laranjeira, Dune & Hugel, Ocean Eng. 200 (2020) 107018). Kinematic robots at a fixed control rate, exact "
      "features, optional leader path, pushes and model errors; a lumped-mass cable shows how far the "
      "quasi-static catenary holds.",
      tether::tetherBinder(), tether::checkTetherParameters,
      [](const TetherParameters& p, RunContext& context) {
        const tether::SimulationOutput sim = tether::simulateTether(p, context);
        return tether::buildTetherResults(p, sim, context);
      });
}

}  // namespace maris
