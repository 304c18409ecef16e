// What a run will cost, estimated from its parameters before it starts, and the limits beyond which a
// front end (maris-cli, the GUI) refuses to start it unless the user allows a large run. A scene provides
// the estimate in its registry entry (SceneDefinition::estimate); the limits are the same for every scene.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace maris {

// One estimated quantity with the parameters (paths below "parameters") that set it. 0 = not estimated.
struct WorkQuantity {
  double value = 0.0;
  std::vector<std::string> parameters;
};

struct WorkEstimate {
  WorkQuantity steps;         // time steps, iterations or frequency/speed points the solver loops over
  WorkQuantity cells;         // unknowns of the largest system (segments, mesh cells, panels, dense matrix order)
  WorkQuantity samples;       // numbers kept for the results (table entries, 3D frame points)
  WorkQuantity memory_bytes;  // peak memory of the solve [bytes]
  WorkQuantity seconds;       // longest call that cannot be stopped once started (dense eigen solve, FFT) [s], from its size
  double output_bytes = 0.0;  // size of the run's files [bytes] (CSV, JSON, plots)
};

// Generous for real work: minutes to hours of solver time, not days; memory well inside the machine.
struct WorkLimits {
  double steps = 2e8;
  double cells = 5e6;
  double samples = 2e8;
  double memory_bytes = 8e9;  // also at most half of the machine's physical memory (defaultWorkLimits)
  double seconds = 5.0;       // such a call keeps a core busy after a cancellation (core/abandonable.hpp) or delays it
};

WorkLimits defaultWorkLimits();

// One error per quantity beyond its limit, at the path of its first parameter, naming every parameter that
// sets it, the estimate and the limit. Empty when the run is within the limits.
std::vector<FieldError> workLimitErrors(const WorkEstimate& estimate, const WorkLimits& limits = defaultWorkLimits());

// Bytes of the CSV text of `values` numbers (17 significant digits and a separator each) plus `plots` PNGs.
double csvOutputBytes(double values, int plots = 0);

}  // namespace maris
