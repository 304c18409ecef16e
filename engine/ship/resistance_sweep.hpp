// Michell wave resistance over many speeds, in parallel (std::thread). Every speed is computed by exactly
// the same sequence of operations whatever thread runs it, so the results do not depend on the thread count.
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

// R_W at every speed [m/s]. threads = 0 uses std::thread::hardware_concurrency(). Progress is reported from
// the calling thread under `stage`; cancellation is polled by every thread. The first exception thrown by any
// speed (RunCancelled, SolverError) is rethrown after all threads have stopped.
std::vector<WaveResistance> waveResistanceSweep(const KochinFactory& make_kochin, const std::vector<double>& speeds,
                                                double gravity, double density, const MichellSettings& settings,
                                                int threads, RunContext* context, const std::string& stage);

}  // namespace maris::ship
