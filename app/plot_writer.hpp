// PNG plots for the headless runner, rendered off-screen with the same plot code as the GUI.
#pragma once

#include <filesystem>
#include <vector>

#include "core/results.hpp"

// Writes DIR/<plot name>.png for every PlotSpec; returns the files written (none when the
// build has no GUI libraries).
std::vector<std::filesystem::path> writePlotPngs(const std::filesystem::path& dir, const maris::Results& results,
                                                 int argc, char** argv);
