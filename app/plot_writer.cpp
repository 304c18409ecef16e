#include "plot_writer.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include <dlfcn.h>

#include "core/version.hpp"
#include "plot_renderer_abi.hpp"

namespace maris::cli {

namespace {

namespace fs = std::filesystem;

#ifdef MARIS_PLOT_RENDERER_FILE
// Next to the executable (the build tree), then the installed module folder relative to it
// (MARIS_PLOT_RENDERER_RELDIR, e.g. ../lib/maris/modules from bin/).
std::vector<fs::path> rendererCandidates() {
  std::error_code error;
  const fs::path exe_dir = fs::read_symlink("/proc/self/exe", error).parent_path();
  return {exe_dir / MARIS_PLOT_RENDERER_FILE,
          (exe_dir / MARIS_PLOT_RENDERER_RELDIR / MARIS_PLOT_RENDERER_FILE).lexically_normal()};
}

const PlotRenderer& loadRenderer() {
  std::string tried;
  for (const auto& file : rendererCandidates()) {
    std::error_code error;
    if (!fs::exists(file, error)) {
      tried += "\n  " + file.string() + ": not there";
      continue;
    }
    // Never unloaded: Qt keeps threads and handlers for the life of the process.
    void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      tried += "\n  " + file.string() + ": " + ::dlerror();
      continue;
    }
    using Entry = const PlotRenderer* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(handle, kPlotRendererSymbol));
    const PlotRenderer* renderer = entry ? entry() : nullptr;
    if (!renderer) {
      tried += "\n  " + file.string() + ": not a Maris plot renderer (no " + kPlotRendererSymbol + ")";
      continue;
    }
    if (renderer->abi != kPlotRendererAbi || renderer->version != versionText()) {
      tried += "\n  " + file.string() + ": from Maris " + renderer->version + ", this maris-cli is " + versionText();
      continue;
    }
    return *renderer;
  }
  throw PlotRendererMissing("cannot write PNG plots: the plot renderer " + std::string(MARIS_PLOT_RENDERER_FILE) +
                            " of this maris-cli cannot be loaded:" + tried +
                            "\n(reinstall maris-cli, or rebuild it; --no-plots runs without plots)");
}
#endif

// The loaded renderer, or nullptr in a build without one (MARIS_BUILD_GUI=OFF).
const PlotRenderer* renderer() {
#ifdef MARIS_PLOT_RENDERER_FILE
  static const PlotRenderer& loaded = loadRenderer();  // a failure throws, and the next call tries again
  return &loaded;
#else
  static const bool noted = [] {
    std::fprintf(stderr, "note: no PNG plots: this maris-cli was built without the plot renderer\n");
    return true;
  }();
  (void)noted;
  return nullptr;
#endif
}

// What the study plot draws: every varied number parameter's value and the result in each case (NaN
// where a case has none).
ui::StudyPlotData studyPlotData(const study::CollectedStudy& collected, const study::StudyManifest& manifest,
                                const study::StudyPlot& plot, int& x) {
  const Json& study_document = manifest.json.contains("study") ? manifest.json["study"] : manifest.json;
  ui::StudyPlotData data;
  data.title = plot.title;
  data.result_name = collected.result_names[plot.result];
  data.result_unit = collected.result_units[plot.result];
  if (plot.result < collected.result_labels.size()) data.result_label = collected.result_labels[plot.result];
  for (std::size_t p = 0; p < collected.parameters.size(); ++p) {
    const auto& parameter = collected.parameters[p];
    if (parameter.kind != ParamKind::Real && parameter.kind != ParamKind::Integer) continue;
    if (p == plot.x) x = static_cast<int>(data.parameters.size());
    ui::StudyParameterData column{parameter.path, parameter.label, parameter.unit,
                                  study::logSpaced(study_document, parameter.path), {}};
    for (const auto& c : collected.cases)
      column.values.push_back(c.values[p].is_number() ? c.values[p].get<double>() : std::nan(""));
    data.parameters.push_back(std::move(column));
  }
  for (const auto& c : collected.cases) data.result.push_back(c.results[plot.result].value_or(std::nan("")));
  return data;
}

}  // namespace

void requirePlotRenderer() { renderer(); }

}  // namespace maris::cli

std::vector<std::filesystem::path> writePlotPngs(const std::filesystem::path& dir, const maris::Results& results,
                                                 int argc, char** argv) {
  if (results.plots.empty()) return {};
  const auto* renderer = maris::cli::renderer();
  return renderer ? renderer->write_run_pngs(dir, results, argc, argv) : std::vector<std::filesystem::path>{};
}

std::vector<std::filesystem::path> writeStudyPngs(const std::filesystem::path& dir,
                                                  const maris::study::CollectedStudy& collected,
                                                  const maris::study::StudyManifest& manifest, int argc, char** argv) {
  std::vector<maris::cli::StudyPng> pngs;
  for (const auto& plot : maris::study::studyPlots(collected, manifest)) {
    maris::cli::StudyPng png;
    png.data = maris::cli::studyPlotData(collected, manifest, plot, png.x);
    png.kind = plot.heat_map ? maris::ui::StudyPlotKind::HeatMap : maris::ui::StudyPlotKind::Lines;
    png.file = dir / (plot.file_stem + ".png");
    pngs.push_back(std::move(png));
  }
  if (pngs.empty()) return {};
  const auto* renderer = maris::cli::renderer();
  return renderer ? renderer->write_study_pngs(pngs, argc, argv) : std::vector<std::filesystem::path>{};
}
