// maris_plot_renderer.so: the PNG plots of maris-cli, rendered off-screen with the GUI's plot code
// (plots/result_plot.hpp, plots/study_plot.hpp). Loaded by maris-cli only when it writes plots.
#include <QApplication>
#include <QByteArray>

#include <cstdio>
#include <string>

#include "core/version.hpp"
#include "plot_renderer_abi.hpp"
#include "plots/result_plot.hpp"
#include "plots/study_plot.hpp"

namespace {

using maris::cli::StudyPng;
namespace fs = std::filesystem;

// Qt warns when XDG_RUNTIME_DIR is unset or unusable (a Slurm job, a container, a cron job: no login session) and
// falls back to a folder of its own, which off-screen rendering never needs; the warning would be the only line a
// plot-writing run or study collect prints on stderr, and reads like a fault. Every other message passes on.
QtMessageHandler previous_message_handler = nullptr;

void plotMessageHandler(QtMsgType type, const QMessageLogContext& context, const QString& text) {
  if (type == QtWarningMsg && text.startsWith(QLatin1String("QStandardPaths: "))) return;
  if (previous_message_handler)
    previous_message_handler(type, context, text);
  else
    std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, text)));
}

// The filter while one call renders (the module is loaded into maris-cli, whose own messages are not Qt's).
struct QuietRuntimeDirWarning {
  QuietRuntimeDirWarning() { previous_message_handler = qInstallMessageHandler(plotMessageHandler); }
  ~QuietRuntimeDirWarning() { qInstallMessageHandler(previous_message_handler); }
  QuietRuntimeDirWarning(const QuietRuntimeDirWarning&) = delete;
  QuietRuntimeDirWarning& operator=(const QuietRuntimeDirWarning&) = delete;
};

// The CLI never needs a display: Qt's off-screen platform. One application object per call (a process
// writes its plots once).
std::vector<fs::path> writeRunPngs(const fs::path& dir, const maris::Results& results, int argc, char** argv) {
  const QuietRuntimeDirWarning quiet;
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  std::vector<fs::path> files;
  for (const auto& spec : results.plots) {
    const auto file = dir / (spec.name + ".png");
    if (maris::ui::savePlotImage(results, spec, QString::fromStdString(file.string()), 1200, 800))
      files.push_back(file);
  }
  return files;
}

std::vector<fs::path> writeStudyPngs(const std::vector<StudyPng>& pngs, int argc, char** argv) {
  std::vector<fs::path> files;
  if (pngs.empty()) return files;
  const QuietRuntimeDirWarning quiet;
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  for (const auto& png : pngs)
    if (maris::ui::saveStudyPlotImage(png.data, png.x, png.kind, QString::fromStdString(png.file.string()), 1000, 750))
      files.push_back(png.file);
  return files;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const maris::cli::PlotRenderer* maris_plot_renderer() {
  static const std::string version = maris::versionText();
  static const maris::cli::PlotRenderer renderer{maris::cli::kPlotRendererAbi, version.c_str(), writeRunPngs,
                                                 writeStudyPngs};
  return &renderer;
}
