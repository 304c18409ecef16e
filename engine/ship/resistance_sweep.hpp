// Michell wave resistance over many speeds, in parallel (std::thread). Every speed is computed by exactly
// the same sequence of operations whatever thread runs it, so the results do not depend on the thread count,
// on the order in which speeds finish, or on whether anyone watches the sweep.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/run_context.hpp"
#include "ship/michell_resistance.hpp"

namespace maris::ship {

// Makes one Kochin function (with its own workspace) per thread.
using KochinFactory = std::function<std::unique_ptr<KochinFunction>()>;

// One resistance curve of a sweep: its Kochin function and Michell settings.
struct WaveResistanceCurve {
  KochinFactory make_kochin;
  MichellSettings settings;
};

// The rows finished so far: `finished[i]` is true once every curve is computed at speed i, and then
// `values[curve][i]` holds it (other entries are default-constructed). Called on the sweep's calling thread
// only, between row completions, and only when the context wants partial results.
using SweepObserver =
    std::function<void(const std::vector<std::vector<WaveResistance>>& values, const std::vector<bool>& finished)>;

// R_W of every curve at every speed [m/s]: result[curve][speed]. One task computes all curves at one speed, so
// rows finish whole. threads = 0 uses std::thread::hardware_concurrency(). The calling thread only coordinates:
// it reports progress under `stage` after every finished row and, when `observe` is set and the context wants
// partial results, shows it the rows finished so far. Cancellation is polled by every worker. The first exception
// thrown by any speed (RunCancelled, SolverError) is rethrown after all threads have stopped.
std::vector<std::vector<WaveResistance>> waveResistanceSweep(const std::vector<WaveResistanceCurve>& curves,
                                                             const std::vector<double>& speeds, double gravity,
                                                             double density, int threads, RunContext* context,
                                                             const std::string& stage,
                                                             const SweepObserver& observe = {});

// One curve: R_W at every speed [m/s].
std::vector<WaveResistance> waveResistanceSweep(const KochinFactory& make_kochin, const std::vector<double>& speeds,
                                                double gravity, double density, const MichellSettings& settings,
                                                int threads, RunContext* context, const std::string& stage);

}  // namespace maris::ship
