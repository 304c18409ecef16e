#include "plot_writer.hpp"

#include <QApplication>
#include <QByteArray>

#include "plots/result_plot.hpp"

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
