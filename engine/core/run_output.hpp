// Writes a finished run to a folder: scenario.json (exactly what ran), summary.json (scalars with
// units, solver statistics, warnings) and one CSV per result table. Every file is written
// atomically, so a cancelled or failed run never leaves a torn file. PNG plots are added by the
// caller that has a renderer (app/, through ui/).
#pragma once

#include <filesystem>
#include <vector>

#include "core/results.hpp"
#include "core/scenario.hpp"

namespace maris {

// Returns the files written, in order.
std::vector<std::filesystem::path> writeRunFolder(const std::filesystem::path& dir, const Scenario& scenario,
                                                  const Results& results);

}  // namespace maris
