// maris: the desktop application (options: ui/command_line.hpp, `maris --help`).
#include <cstdio>

#include <QApplication>
#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>

#include "command_line.hpp"
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
  // --help and mistakes in the options are answered before Qt starts: they need no display.
  QStringList arguments;
  for (int i = 1; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
  const maris::ui::ParsedCommandLine parsed = maris::ui::parseCommandLine(arguments);
  if (parsed.options.help) {
    std::fputs(maris::ui::commandLineHelp().toLocal8Bit().constData(), stdout);
    return 0;
  }
  if (!parsed.error.isEmpty()) {
    std::fprintf(stderr, "maris: %s\n", parsed.error.toLocal8Bit().constData());
    return 2;
  }
  const maris::ui::CommandLine& options = parsed.options;
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Maris"));
  QApplication::setApplicationName(QStringLiteral("maris"));
  QApplication::setApplicationVersion(QStringLiteral(MARIS_VERSION));
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
    if (!options.screenshot.isEmpty()) return 1;
  }
  if (options.screenshot.isEmpty()) return app.exec();

  // Screenshot mode: run, let the views paint, grab the window, exit.
  int exit_code = 1;
  QObject::connect(&window, &maris::ui::MainWindow::runFinished, &app, [&] {
    const QString problem = maris::ui::applyViewOptions(window, options);
    if (!problem.isEmpty()) {
      std::fprintf(stderr, "maris: %s\n", problem.toLocal8Bit().constData());
      exit_code = 2;
      app.quit();
      return;
    }
    QTimer::singleShot(800, &app, [&] {
      const QImage shot = window.grab().toImage();
      if (shot.save(options.screenshot, "PNG")) {
        std::printf("maris: saved %s (%d x %d)\n", options.screenshot.toLocal8Bit().constData(), shot.width(),
                    shot.height());
        exit_code = 0;
      } else {
        std::fprintf(stderr, "maris: could not write %s\n", options.screenshot.toLocal8Bit().constData());
      }
      app.quit();
    });
  });
  QObject::connect(&window, &maris::ui::MainWindow::runFailed, &app, [&](const QString& message) {
    std::fprintf(stderr, "maris: the run failed: %s\n", message.toLocal8Bit().constData());
    exit_code = 3;
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
