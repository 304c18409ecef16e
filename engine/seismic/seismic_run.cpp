#include <numbers>

#include "seismic/seismic_solve.hpp"

namespace maris::seismic {

Results solveSeismic(const SeismicParameters& p, RunContext& ctx) {
  Results results;
  const FreeField field(seabedMaterial(p), waterLayer(p), waveType(p), p.angle_deg * std::numbers::pi / 180.0);
  addFreeFieldResults(p, field, results, ctx);
  ctx.progress(1.0, "done");
  return results;
}

}  // namespace maris::seismic
