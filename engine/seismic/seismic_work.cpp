// The seismic scene's work estimate: the FE runs' steps from the main mesh's stable step, their memory from the
// boundary drive's free-field histories (one per node row, as long as the run) and the recorded stations.
#include <algorithm>
#include <cmath>
#include <thread>

#include "seismic/fe_mesh.hpp"
#include "seismic/fe_model.hpp"
#include "seismic/seismic_solve.hpp"

namespace maris::seismic {

WorkEstimate estimateSeismicWork(const SeismicParameters& p) {
  const FeModel model = buildFeModel(buildMesh(p, p.include_water));
  const FeMesh& m = model.mesh;
  const bool reef = p.model == "reef";
  const double jobs = 1.0 + (reef ? 1.0 : 0.0) + (reef && p.include_water && p.compare_without_water ? 1.0 : 0.0) +
                      static_cast<double>(p.sweep_angles_deg.size());
  const double steps = std::ceil(p.duration / (p.courant_fraction * model.stable_step));
  const std::vector<std::string> step_parameters = {"solver.courant_fraction", "solver.duration",
                                                    "solver.cutoff_frequency", "incidence.sweep_angles_deg"};
  WorkEstimate w;
  w.steps = {jobs * steps, step_parameters};
  w.cells = {static_cast<double>(m.cellCount()), {"solver.cutoff_frequency", "geometry.flat_width",
                                                  "geometry.seabed_thickness", "geometry.lateral_water_width"}};
  const double recorded = 2.0 * (p.station_count + 2) * (steps + 1);
  const double snapshots = static_cast<double>(p.snapshot_count) * m.nodeCount();
  w.samples = {jobs * recorded + snapshots, {"solver.courant_fraction", "solver.duration", "output.station_count"}};
  // Per running job: three free-field histories (u_x, u_y, φ) per node row, the records, the model's arrays.
  constexpr double kDoublesPerNode = 24;
  const double per_job = 8.0 * (3.0 * (m.ny + 1) * steps + recorded + kDoublesPerNode * m.nodeCount());
  const double concurrent = std::min(jobs, static_cast<double>(std::max(1u, std::thread::hardware_concurrency())));
  w.memory_bytes = {concurrent * per_job + 8.0 * snapshots, step_parameters};
  w.output_bytes = csvOutputBytes(recorded + snapshots / 4, 10);
  // The free-field synthesis' FFTs (FreeFieldSynthesis: ≥ 2× the trace, 8× beyond the SV critical angle) cannot be
  // cancelled; FFTW (FFTW_ESTIMATE plans, as core/spectrum makes them) measured at 1.26e-9 s per n·log2 n for
  // n = 2^20 and 2^22 on a 2-core machine (26 ms and 116 ms), taken twice for a loaded one.
  constexpr double kFftSecondsPerButterflyLevel = 2.5e-9;
  const double trace = steps + 8;
  const double n_fft = std::exp2(std::ceil(std::log2(8.0 * trace)));
  w.seconds = {kFftSecondsPerButterflyLevel * n_fft * std::log2(n_fft), step_parameters};
  return w;
}

}  // namespace maris::seismic
