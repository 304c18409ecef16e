// PNG plots for the headless runner, rendered off-screen with the same plot code as the GUI. The renderer
// is a module (maris_plot_renderer.so, plot_renderer_abi.hpp) loaded on first use, so that maris-cli itself
// links no Qt and starts fast when it writes no plots.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "core/results.hpp"
#include "study/study_collect.hpp"

namespace maris::cli {

// The plot renderer cannot be loaded (missing, or from another build): exit code 1, with where it was
// looked for and what to do.
class PlotRendererMissing : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Loads the renderer now (once per process), so that a command that will write plots refuses before it
// runs anything; throws PlotRendererMissing. Does nothing in a build without the GUI libraries.
void requirePlotRenderer();

}  // namespace maris::cli

// Writes DIR/<plot name>.png for every PlotSpec; returns the files written (none when the
// build has no GUI libraries). Throws maris::cli::PlotRendererMissing.
std::vector<std::filesystem::path> writePlotPngs(const std::filesystem::path& dir, const maris::Results& results,
                                                 int argc, char** argv);

// Writes DIR/<file stem>.png for every plot of a collected study (studyPlots: a result against a parameter,
// or a heat map); returns the files written (none without the GUI libraries). Throws PlotRendererMissing.
std::vector<std::filesystem::path> writeStudyPngs(const std::filesystem::path& dir,
                                                  const maris::study::CollectedStudy& collected,
                                                  const maris::study::StudyManifest& manifest, int argc, char** argv);
