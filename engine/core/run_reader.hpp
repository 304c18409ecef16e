// Reads a run folder (what writeRunFolder wrote: `maris-cli run --out DIR`, a study's case folder) back into
// Results, so a front end can show a run that another process made: its scalars, every table, the plots'
// layouts, the solver statistics and the warnings. A run folder holds no 3D view.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/results.hpp"

namespace maris {

struct RunFolderContents {
  Results results;                  // View3D empty: a run folder stores no 3D view
  std::vector<std::string> missing;  // what the folder could not give, in words ("the 3D view (not stored …)")
};

// Throws InputError naming the file when DIR holds no complete run (no summary.json, one that does not parse) or a
// table it lists cannot be read. Plots: from summary.json's "plots" (Maris 0.9.0 and earlier wrote none: then
// `missing` says so and the tables are all there is), each kept only when its table and columns are there.
RunFolderContents readRunFolder(const std::filesystem::path& dir);

}  // namespace maris
