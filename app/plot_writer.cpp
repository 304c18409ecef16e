#include "plot_writer.hpp"

#include <QApplication>
#include <QByteArray>

#include <cmath>

#include "plots/result_plot.hpp"
#include "plots/study_plot.hpp"

std::vector<std::filesystem::path> writePlotPngs(const std::filesystem::path& dir, const maris::Results& results,
                                                 int argc, char** argv) {
  // The CLI never needs a display: render with Qt's off-screen platform.
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  std::vector<std::filesystem::path> files;
  for (const auto& spec : results.plots) {
    const auto file = dir / (spec.name + ".png");
    if (maris::ui::savePlotImage(results, spec, QString::fromStdString(file.string()), 1200, 800))
      files.push_back(file);
  }
  return files;
}

namespace {

// What the study plot draws: every varied number parameter's value and the result in each case (NaN
// where a case has none).
maris::ui::StudyPlotData studyPlotData(const maris::study::CollectedStudy& collected,
                                       const maris::study::StudyManifest& manifest, const maris::study::StudyPlot& plot,
                                       int& x) {
  const maris::Json& study_document = manifest.json.contains("study") ? manifest.json["study"] : manifest.json;
  maris::ui::StudyPlotData data;
  data.title = plot.title;
  data.result_name = collected.result_names[plot.result];
  data.result_unit = collected.result_units[plot.result];
  for (std::size_t p = 0; p < collected.parameters.size(); ++p) {
    const auto& parameter = collected.parameters[p];
    if (parameter.kind != maris::ParamKind::Real && parameter.kind != maris::ParamKind::Integer) continue;
    if (p == plot.x) x = static_cast<int>(data.parameters.size());
    maris::ui::StudyParameterData column{parameter.path, parameter.unit, maris::study::logSpaced(study_document, parameter.path),
                                         {}};
    for (const auto& c : collected.cases)
      column.values.push_back(c.values[p].is_number() ? c.values[p].get<double>() : std::nan(""));
    data.parameters.push_back(std::move(column));
  }
  for (const auto& c : collected.cases) data.result.push_back(c.results[plot.result].value_or(std::nan("")));
  return data;
}

}  // namespace

std::vector<std::filesystem::path> writeStudyPngs(const std::filesystem::path& dir,
                                                  const maris::study::CollectedStudy& collected,
                                                  const maris::study::StudyManifest& manifest, int argc, char** argv) {
  std::vector<std::filesystem::path> files;
  const auto plots = maris::study::studyPlots(collected, manifest);
  if (plots.empty()) return files;
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  for (const auto& plot : plots) {
    int x = 0;
    const maris::ui::StudyPlotData data = studyPlotData(collected, manifest, plot, x);
    const auto file = dir / (plot.file_stem + ".png");
    const auto kind = plot.heat_map ? maris::ui::StudyPlotKind::HeatMap : maris::ui::StudyPlotKind::Lines;
    if (maris::ui::saveStudyPlotImage(data, x, kind, QString::fromStdString(file.string()), 1000, 750))
      files.push_back(file);
  }
  return files;
}
