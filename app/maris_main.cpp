// maris: the desktop application.
//   maris [SCENARIO]                        open a scenario file or a built-in scenario
//   maris --screenshot FILE [--scenario NAME] [--size WxH]
//                                           open, run to completion, save a picture of the window, exit
//   maris --help
#include <cstdio>
#include <cstring>
#include <string>

#include <QApplication>
#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>

#include "document/scenario_document.hpp"
#include "main_window.hpp"
#include "scene_library.hpp"

namespace {

const char* kHelp =
    "usage: maris [SCENARIO]\n"
    "       maris --screenshot FILE [--scenario SCENARIO] [--size WxH] [--theme light|dark]\n"
    "\n"
    "The Maris desktop application: pick a scenario, edit its parameters, run it, and see the\n"
    "results as plots and in 3D.\n"
    "\n"
    "  SCENARIO               a scenario file (*.json) or a built-in scenario name (see `maris-cli list`)\n"
    "  --screenshot FILE      open SCENARIO (default: the default built-in), run it to completion,\n"
    "                         save a PNG of the main window with its results, and exit\n"
    "                         (exit code 0 on success, 3 if the run failed, 1 on other errors)\n"
    "  --size WxH             window size for --screenshot (default 1600x1000)\n"
    "  --theme NAME           light, dark or system (the platform's palette); remembered\n"
    "  --help                 this text\n";

struct Options {
  QString scenario;
  QString screenshot;
  QString theme;
  int width = 1600, height = 1000;
};

bool parse(int argc, char** argv, Options& options) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto next = [&](QString& out) {
      if (i + 1 >= argc) return false;
      out = QString::fromLocal8Bit(argv[++i]);
      return true;
    };
    if (arg == "--screenshot") {
      if (!next(options.screenshot)) return false;
    } else if (arg == "--scenario") {
      if (!next(options.scenario)) return false;
    } else if (arg == "--theme") {
      QString theme;
      if (!next(theme) || (theme != "light" && theme != "dark" && theme != "system")) return false;
      options.theme = theme;
    } else if (arg == "--size") {
      QString size;
      if (!next(size) || std::sscanf(size.toLatin1().constData(), "%dx%d", &options.width, &options.height) != 2)
        return false;
    } else if (!arg.empty() && arg[0] != '-') {
      options.scenario = QString::fromLocal8Bit(argv[i]);
    } else {
      return false;
    }
  }
  return true;
}

bool openScenario(maris::ui::MainWindow& window, const QString& scenario) {
  if (scenario.isEmpty()) return !window.document()->isEmpty();
  if (QFileInfo::exists(scenario)) return window.openFile(scenario);
  return window.openExample(scenario);
}

}  // namespace

int main(int argc, char** argv) {
  // --help must work without a display, so it is answered before Qt starts.
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::fputs(kHelp, stdout);
      return 0;
    }
  Options options;
  if (!parse(argc, argv, options)) {
    std::fputs(kHelp, stderr);
    return 1;
  }
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
