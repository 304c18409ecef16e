// Writes a finished run to a folder: scenario.json (exactly what ran), summary.json (scalars with
// units, solver statistics, warnings; which Maris ran it: maris_version, commit, started_at in UTC,
// host_threads) and one CSV per result table. The CLI's run folder and the GUI's report folder both
// come from here, into a RunFolder's staging folder: the files are written in place there, and
// RunFolder::commit syncs them and moves the folder into place whole, so a cancelled or failed run never
// leaves a torn file (one sync pass at the end instead of one per file: a small run's cost was mostly
// its syncs). PNG plots are added by the caller that has a renderer (app/, through ui/).
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "core/results.hpp"
#include "core/scenario.hpp"

namespace maris {

// "2026-11-28T11:12:08Z": ISO 8601, UTC, whole seconds (started_at in summary.json, a study's timings).
std::string isoUtc(std::chrono::system_clock::time_point t);

// Returns the files written, in order. `started_at`: when the run started (the caller took the time
// just before runScenario).
std::vector<std::filesystem::path> writeRunFolder(const std::filesystem::path& dir, const Scenario& scenario,
                                                  const Results& results,
                                                  std::chrono::system_clock::time_point started_at);

}  // namespace maris
