// `maris`'s command line (ui/command_line.*): what a --screenshot shows (3D frame or time, colour
// map, plot tab, size, theme), --help and --version, and the messages and exit code (1) for bad
// options and values, on Qt's offscreen platform with the test scene (10 frames at t = 0, 0.1, …,
// 0.9 s; plots "deflection" and "tip_motion").
#include <QSignalSpy>
#include <QTabWidget>
#include <QtTest>

#include "command_line.hpp"
#include "core/version.hpp"
#include "main_window.hpp"
#include "plots/plot_panel.hpp"
#include "test_scene.hpp"
#include "ui_test_support.hpp"
#include "view3d/scene_view.hpp"

using namespace maris;
using namespace maris::ui;

class CommandLineTest : public QObject {
  Q_OBJECT

 private:
  // A main window that has run the test scene's default example.
  std::unique_ptr<MainWindow> ranWindow() {
    auto window = std::make_unique<MainWindow>(test::rodLibrary());
    window->resize(1200, 800);
    window->show();
    if (!window->openExample(QStringLiteral("rod_default"))) return nullptr;
    QSignalSpy finished(window.get(), &MainWindow::runFinished);
    if (!window->startRun() || !finished.wait(20000)) return nullptr;
    return window;
  }

  static CommandLine parsed(const QStringList& arguments) {
    const ParsedCommandLine p = parseCommandLine(arguments);
    [&] { QVERIFY2(p.error.isEmpty(), qPrintable(p.error)); }();
    return p.options;
  }

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void everyOptionIsRead() {
    const CommandLine o = parsed({"--screenshot", "out.png", "--scenario", "riser_default", "--size", "800x600",
                                  "--theme", "dark", "--time", "12.5", "--tab", "top_force", "--colormap", "viridis"});
    QCOMPARE(o.screenshot, QStringLiteral("out.png"));
    QCOMPARE(o.scenario, QStringLiteral("riser_default"));
    QCOMPARE(o.width, 800);
    QCOMPARE(o.height, 600);
    QCOMPARE(o.theme, QStringLiteral("dark"));
    QVERIFY(o.time && *o.time == 12.5);
    QVERIFY(!o.frame);
    QCOMPARE(o.tab, QStringLiteral("top_force"));
    QVERIFY(o.color_map == ColorMap::Viridis);
    QCOMPARE(parsed({"scenario.json", "--frame", "3", "--screenshot", "x.png"}).frame, std::optional<int>(3));
    // The help lists every option and every colour map.
    for (const char* word : {"--screenshot FILE", "--scenario", "--size WxH", "--theme", "--frame K", "--time T",
                             "--tab PLOT", "--colormap MAP", "cool-warm", "viridis", "rainbow", "greyscale",
                             "--version", "Exit codes"})
      QVERIFY2(commandLineHelp().contains(QLatin1String(word)), word);
  }

  // --help and --version stop before the application starts, with exit code 0 and their text.
  void helpAndVersionExitZero() {
    for (const char* flag : {"--help", "-h"}) {
      const ParsedCommandLine help = parseCommandLine({flag});
      QCOMPARE(help.exit_code, std::optional<int>(0));
      QCOMPARE(help.output, commandLineHelp());
      QVERIFY(help.error.isEmpty());
    }
    const ParsedCommandLine version = parseCommandLine({"--version"});
    QCOMPARE(version.exit_code, std::optional<int>(0));
    QCOMPARE(version.output, QString::fromStdString("maris " + versionText() + "\n"));
    QVERIFY(version.output.startsWith(QStringLiteral("maris " MARIS_TEST_PROJECT_VERSION)));
    QVERIFY(!parseCommandLine({"--screenshot", "x.png"}).exit_code);  // a command line that starts maris
  }

  void badValuesNameTheOptionAndWhatIsAllowed_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("expected");  // pieces of the message
    const QStringList shot{"--screenshot", "x.png"};
    QTest::newRow("unknown colour map") << shot + QStringList{"--colormap", "pink"}
                                        << QStringList{"--colormap pink", "cool-warm, viridis, rainbow, greyscale"};
    QTest::newRow("size too small") << QStringList{"--size", "100x50"} << QStringList{"--size 100x50", "[200, 8000]"};
    QTest::newRow("size not WxH") << QStringList{"--size", "big"} << QStringList{"--size big", "WIDTHxHEIGHT"};
    QTest::newRow("frame zero") << shot + QStringList{"--frame", "0"} << QStringList{"--frame 0", "from 1"};
    QTest::newRow("time not a number") << shot + QStringList{"--time", "soon"} << QStringList{"--time soon", "seconds"};
    QTest::newRow("unknown theme") << QStringList{"--theme", "blue"} << QStringList{"--theme blue", "light, dark, system"};
    QTest::newRow("unknown option") << QStringList{"--zoom", "2"} << QStringList{"unknown option --zoom"};
    QTest::newRow("misspelt option") << QStringList{"--colourmap", "viridis"}
                                     << QStringList{"unknown option --colourmap; did you mean --colormap?"};
    QTest::newRow("missing value") << QStringList{"--screenshot"} << QStringList{"--screenshot needs a value (FILE)"};
    QTest::newRow("missing value before an option") << QStringList{"x.json", "--theme"}
                                                    << QStringList{"--theme needs a value (NAME)"};
    QTest::newRow("frame and time") << shot + QStringList{"--frame", "2", "--time", "1"}
                                    << QStringList{"--frame and --time"};
    QTest::newRow("tab without screenshot") << QStringList{"--tab", "top_force"} << QStringList{"--screenshot FILE"};
    QTest::newRow("two scenarios") << QStringList{"a.json", "b.json"} << QStringList{"unexpected extra argument 'b.json'"};
    QTest::newRow("scenario twice") << QStringList{"--scenario", "a.json", "b.json"}
                                    << QStringList{"b.json", "only one scenario", "--scenario a.json"};
  }
  void badValuesNameTheOptionAndWhatIsAllowed() {
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, expected);
    const ParsedCommandLine parsed = parseCommandLine(arguments);
    for (const QString& piece : expected)
      QVERIFY2(parsed.error.contains(piece), qPrintable(QStringLiteral("'%1' lacks '%2'").arg(parsed.error, piece)));
    QCOMPARE(parsed.exit_code, std::optional<int>(1));  // a usage error
  }

  void viewOptionsChooseFrameTabAndColourMap() {
    auto window = ranWindow();
    QVERIFY(window);
    SceneView* view = window->sceneView();
    QCOMPARE(view->frameCount(), 10);
    QCOMPARE(applyViewOptions(*window, parsed({"--screenshot", "x.png", "--frame", "3", "--tab", "tip_motion",
                                               "--colormap", "greyscale"})),
             QString());
    QCOMPARE(view->currentFrame(), 2);  // frames are counted from 1 on the command line
    QCOMPARE(window->plots()->currentView()->spec().name, std::string("tip_motion"));
    QVERIFY(view->colorSettings().map == ColorMap::Greyscale);
    // A time picks the nearest frame (t = 0.5 s is frame index 5); a tab's title works as well.
    QCOMPARE(applyViewOptions(*window, parsed({"--screenshot", "x.png", "--time", "0.52", "--tab", "Deflection"})),
             QString());
    QCOMPARE(view->currentFrame(), 5);
    QCOMPARE(window->plots()->currentView()->spec().name, std::string("deflection"));
  }

  void viewOptionsOutsideThisRunAreRefused_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("frame after the last") << QStringList{"--frame", "11"} << QStringList{"--frame 11", "[1, 10]"};
    QTest::newRow("time after the last") << QStringList{"--time", "5"} << QStringList{"--time 5", "[0, 0.9] s"};
    QTest::newRow("unknown plot") << QStringList{"--tab", "stress"}
                                  << QStringList{"--tab stress", "deflection, tip_motion"};
  }
  void viewOptionsOutsideThisRunAreRefused() {
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, expected);
    auto window = ranWindow();
    QVERIFY(window);
    const int frame = window->sceneView()->currentFrame();
    const QString error = applyViewOptions(*window, parsed(QStringList{"--screenshot", "x.png"} + arguments));
    for (const QString& piece : expected)
      QVERIFY2(error.contains(piece), qPrintable(QStringLiteral("'%1' lacks '%2'").arg(error, piece)));
    QCOMPARE(window->sceneView()->currentFrame(), frame);  // nothing changed
  }
};

QTEST_MAIN(CommandLineTest)
#include "test_command_line.moc"
