// Registry entry of the tether scene.
#include <cmath>

#include "core/scene.hpp"
#include "tether/tether_parameters.hpp"
#include "tether/tether_plausibility.hpp"
#include "tether/tether_results.hpp"

namespace maris {

namespace {

// Cable steps (substeps of every control tick) over the simulated time; the histories and 3D frames kept.
WorkEstimate estimateTetherWork(const tether::TetherParameters& p) {
  constexpr double kHistoryColumns = 40;
  const double ticks = std::ceil(p.duration * p.control_rate);
  WorkEstimate w;
  w.steps = {ticks * p.cable_substeps, {"simulation.duration", "control.rate", "cable.substeps"}};
  w.cells = {static_cast<double>(p.cable_segments), {"cable.segments"}};
  w.samples = {kHistoryColumns * ticks + 4.0 * p.animation_frames * (p.cable_segments + 1.0),
               {"simulation.duration", "control.rate", "output.animation_frames", "cable.segments"}};
  w.memory_bytes = {8.0 * w.samples.value, w.samples.parameters};
  w.output_bytes = csvOutputBytes(kHistoryColumns * ticks, 8);
  return w;
}

}  // namespace

SceneDefinition makeTetherScene() {
  using tether::TetherParameters;
  SceneDefinition scene = makeScene<TetherParameters>(
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
  setWorkEstimate<TetherParameters>(scene, tether::tetherBinder(), estimateTetherWork);
  setPlausibility<TetherParameters>(scene, tether::tetherBinder(), tether::tetherPlausibility);
  return scene;
}

}  // namespace maris
