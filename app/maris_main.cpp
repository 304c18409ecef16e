// maris: the desktop application (options: ui/command_line.hpp, `maris --help`).
#include <cstdio>

#include <QApplication>
#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>

#include "cli_conventions.hpp"
#include "command_line.hpp"
#include "core/version.hpp"
#include "document/scenario_document.hpp"
#include "main_window.hpp"
#include "scene_library.hpp"

namespace {

bool openScenario(maris::ui::MainWindow& window, const QString& scenario) {
  if (scenario.isEmpty()) return !window.document()->isEmpty();
  if (QFileInfo::exists(scenario)) return window.openFile(scenario);
  return window.openExample(scenario);
}

}  // namespace

int main(int argc, char** argv) {
  // --help, --version and mistakes in the options are answered before Qt starts: they need no display.
  QStringList arguments;
  for (int i = 1; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
  const maris::ui::ParsedCommandLine parsed = maris::ui::parseCommandLine(arguments);
  if (parsed.exit_code) {
    if (!parsed.error.isEmpty())
      std::fputs(maris::cli::usageErrorText("maris", parsed.error.toStdString()).c_str(), stderr);
    std::fputs(parsed.output.toLocal8Bit().constData(), *parsed.exit_code == maris::cli::kExitOk ? stdout : stderr);
    return *parsed.exit_code;
  }
  const maris::ui::CommandLine& options = parsed.options;
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Maris"));
  QApplication::setApplicationName(QStringLiteral("maris"));
  QApplication::setApplicationVersion(QString::fromStdString(maris::versionText()));
  // A screenshot shows the default layout, not the user's saved one, and leaves the user's
  // settings (layout, recent files) untouched: settings live in a temporary folder.
  QTemporaryDir screenshot_settings;
  if (!options.screenshot.isEmpty() && screenshot_settings.isValid())
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, screenshot_settings.path());

  maris::ui::MainWindow window(maris::ui::SceneLibrary::fromEngine());
  if (!options.theme.isEmpty()) window.setTheme(maris::ui::themeFromKey(options.theme));
  if (!options.screenshot.isEmpty()) window.resize(options.width, options.height);
  window.show();
  if (!openScenario(window, options.scenario)) {
    std::fprintf(stderr, "maris: could not open '%s': %s\n", options.scenario.toLocal8Bit().constData(),
                 window.lastError().toLocal8Bit().constData());
    if (!options.screenshot.isEmpty()) return maris::cli::kExitInvalidInput;
  }
  if (options.screenshot.isEmpty()) return app.exec();

  // Screenshot mode: run, let the views paint, grab the window, exit.
  int exit_code = maris::cli::kExitInvalidInput;  // unless the run finishes and the PNG is written
  QObject::connect(&window, &maris::ui::MainWindow::runFinished, &app, [&] {
    const QString problem = maris::ui::applyViewOptions(window, options);
    if (!problem.isEmpty()) {
      std::fputs(maris::cli::usageErrorText("maris", problem.toStdString()).c_str(), stderr);
      exit_code = maris::cli::kExitUsage;
      app.quit();
      return;
    }
    QTimer::singleShot(800, &app, [&] {
      const QImage shot = window.grab().toImage();
      if (shot.save(options.screenshot, "PNG")) {
        std::printf("maris: saved %s (%d x %d)\n", options.screenshot.toLocal8Bit().constData(), shot.width(),
                    shot.height());
        exit_code = maris::cli::kExitOk;
      } else {
        std::fprintf(stderr, "maris: could not write %s\n", options.screenshot.toLocal8Bit().constData());
        exit_code = maris::cli::kExitUsage;
      }
      app.quit();
    });
  });
  QObject::connect(&window, &maris::ui::MainWindow::runFailed, &app, [&](const QString& message) {
    std::fprintf(stderr, "maris: the run failed: %s\n", message.toLocal8Bit().constData());
    exit_code = maris::cli::kExitSolverFailure;
    app.quit();
  });
  QTimer::singleShot(300, &window, [&] {
    if (!window.startRun()) {
      std::fprintf(stderr, "maris: the scenario cannot run (invalid values?)\n");
      app.quit();
    }
  });
  app.exec();
  return exit_code;
}
