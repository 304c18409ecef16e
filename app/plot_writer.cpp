#include "plot_writer.hpp"

#include <QApplication>
#include <QByteArray>

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

std::vector<std::filesystem::path> writeStudyPngs(const std::filesystem::path& dir,
                                                  const std::vector<maris::study::StudyPlot>& plots, int argc,
                                                  char** argv) {
  std::vector<std::filesystem::path> files;
  if (plots.empty()) return files;
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  using maris::ui::axisLabel;
  for (const auto& p : plots) {
    const auto file = dir / (p.file_stem + ".png");
    const QString name = QString::fromStdString(file.string());
    bool ok = false;
    if (p.heat_map) {
      maris::ui::StudyHeatMap map{QString::fromStdString(p.title), axisLabel(p.x_name, p.x_unit),
                                  axisLabel(p.y_name, p.y_unit), axisLabel(p.z_name, p.z_unit), p.x, p.y, p.z};
      ok = maris::ui::saveStudyHeatMapImage(map, name, 1000, 800);
    } else {
      maris::ui::StudyPoints points{QString::fromStdString(p.title), axisLabel(p.x_name, p.x_unit),
                                    axisLabel(p.y_name, p.y_unit), p.x, p.y, p.line};
      ok = maris::ui::saveStudyPointsImage(points, name, 1000, 700);
    }
    if (ok) files.push_back(file);
  }
  return files;
}
