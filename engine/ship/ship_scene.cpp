// Registry entry of the ship resistance scene.
#include <optional>

#include "core/scene.hpp"
#include "ship/ship_study.hpp"

namespace maris {

SceneDefinition makeShipScene() {
  using ship::ShipParameters;
  return makeScene<ShipParameters>(
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
}

}  // namespace maris
