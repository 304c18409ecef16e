// The interface between maris-cli and its plot renderer, the module maris_plot_renderer.so (Qt and
// QCustomPlot, app/plot_renderer_module.cpp). maris-cli links no Qt: it loads the module with dlopen the
// first time it writes a PNG (plot_writer.cpp), so a run with --no-plots, and every case process of a
// study, starts without mapping Qt. Both sides come from the same build (the module is checked against
// maris-cli's version), so the C++ types below cross the boundary as they are.
#pragma once

#include <filesystem>
#include <vector>

#include "core/results.hpp"
#include "plots/study_plot_data.hpp"

namespace maris::cli {

// One PNG of a study: the result against parameter `x` (lines) or over `x` and the other one (heat map).
struct StudyPng {
  ui::StudyPlotData data;
  int x = 0;
  ui::StudyPlotKind kind = ui::StudyPlotKind::Lines;
  std::filesystem::path file;
};

// Raised by one when the layout of these types or the functions change.
inline constexpr int kPlotRendererAbi = 2;

struct PlotRenderer {
  int abi = kPlotRendererAbi;
  const char* version = "";  // versionText() of the build the module comes from
  // DIR/<plot name>.png for every PlotSpec of `results`; returns the files written.
  std::vector<std::filesystem::path> (*write_run_pngs)(const std::filesystem::path& dir, const Results& results,
                                                       int argc, char** argv) = nullptr;
  // Every PNG of `pngs`; returns the files written.
  std::vector<std::filesystem::path> (*write_study_pngs)(const std::vector<StudyPng>& pngs, int argc,
                                                         char** argv) = nullptr;
};

}  // namespace maris::cli

// The module's one exported symbol.
extern "C" const maris::cli::PlotRenderer* maris_plot_renderer();
inline constexpr const char* kPlotRendererSymbol = "maris_plot_renderer";
