// Registry entry of the ship resistance scene.
#include <algorithm>
#include <optional>
#include <thread>

#include "core/scene.hpp"
#include "ship/ship_plausibility.hpp"
#include "ship/ship_study.hpp"

namespace maris {

namespace {

// Speeds, hull grid and what the results keep. Each sweep thread holds its own Kochin function over the grid.
WorkEstimate estimateShipWork(const ship::ShipParameters& p) {
  constexpr double kColumnsPerSpeed = 24;  // resistance, coefficients, error estimates per curve
  constexpr double kDoublesPerGridPoint = 16;
  const double grid = static_cast<double>(p.stations) * p.waterlines;
  const unsigned threads = p.threads > 0 ? static_cast<unsigned>(p.threads) : std::max(1u, std::thread::hardware_concurrency());
  WorkEstimate w;
  w.steps = {static_cast<double>(p.froude_count), {"speed.count"}};
  w.cells = {grid, {"numerics.stations", "numerics.waterlines"}};
  w.samples = {kColumnsPerSpeed * p.froude_count + 3.0 * grid, {"speed.count", "numerics.stations", "numerics.waterlines"}};
  w.memory_bytes = {8.0 * kDoublesPerGridPoint * grid * (1.0 + threads), {"numerics.stations", "numerics.waterlines"}};
  w.output_bytes = csvOutputBytes(kColumnsPerSpeed * p.froude_count, 6);
  return w;
}

}  // namespace

SceneDefinition makeShipScene() {
  using ship::ShipParameters;
  SceneDefinition scene = makeScene<ShipParameters>(
      "ship", "Ship wave resistance",
      "Resistance curves of a ship hull: Michell's thin-ship wave resistance (accurate Filon/exp-fitted "
      "quadrature with error estimates), the boundary-layer tangency and wave-number corrections of Basic, "
      "Blagojevic & Andrun (Ocean Eng., c. 2020), ITTC-57 friction with a form factor, and Holtrop-Mennen for "
      "comparison. Hulls: Wigley, a parametric family, Series 60, KCS or an offsets CSV.",
      ship::shipSchemaBinder(), ship::checkShipParameters,
      [](const ShipParameters& p, RunContext& context) {
        const ship::ShipModel model = ship::buildShipModel(p, context);
        // Live plots: the rows finished so far, whenever the context wants partial results (else nothing is built).
        std::optional<ship::PartialShipResults> partial;
        const auto publish = [&](const ship::ResistanceCurves& rows_so_far) {
          if (!partial) partial.emplace(p, model);
          context.publishPartial(partial->build(rows_so_far));
        };
        const ship::ResistanceCurves curves = ship::computeResistanceCurves(p, model, context, publish);
        Results results = ship::buildShipResults(p, model, curves, context);
        context.progress(1.0, "done");
        return results;
      });
  setWorkEstimate<ShipParameters>(scene, ship::shipSchemaBinder(), estimateShipWork);
  setPlausibility<ShipParameters>(scene, ship::shipSchemaBinder(), ship::shipPlausibility);
  return scene;
}

}  // namespace maris
