// The run controller (worker thread, progress, partial results, cancel, failure) and the plots
// and exports fed by its results, on Qt's offscreen platform.
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

#include <fstream>
#include <thread>

#include "core/version.hpp"
#include "plots/plot_export.hpp"
#include "plots/plot_panel.hpp"
#include "plots/plot_view.hpp"
#include "run/run_controller.hpp"
#include "plots/result_plot.hpp"
#include "run/run_history.hpp"
#include "test_scene.hpp"
#include "theme.hpp"
#include "themed_icon.hpp"
#include "ui_test_support.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

Scenario rodScenario(double delay, bool fail = false) {
  Scenario s = defaultScenario(test::makeRodScene());
  s.parameters["run"]["delay"] = delay;
  s.parameters["run"]["fail"] = fail;
  return s;
}

// A table "line" of y = x² over x = 0 … n − 1 [m, N], as a live run's growing history would be.
std::shared_ptr<const Results> growingLine(int n) {
  auto r = std::make_shared<Results>();
  Table& t = r->tables.emplace_back();
  t.name = "line";
  std::vector<double> x, y;
  for (int i = 0; i < n; ++i) {
    x.push_back(i);
    y.push_back(double(i) * i);
  }
  t.add("x", "m", x);
  t.add("y", "N", y);
  return r;
}

// Alpha-weighted mean luminance (0 black … 1 white, Rec. 601 weights) of an icon's visible pixels.
double glyphLuminance(const QImage& icon) {
  double sum = 0.0, weight = 0.0;
  for (int y = 0; y < icon.height(); ++y)
    for (int x = 0; x < icon.width(); ++x) {
      const QColor c = icon.pixelColor(x, y);
      sum += c.alphaF() * qGray(c.rgb()) / 255.0;
      weight += c.alphaF();
    }
  return weight > 0 ? sum / weight : -1.0;
}

}  // namespace

class RunTest : public QObject {
  Q_OBJECT

  SceneDefinition scene_ = test::makeRodScene();

  // Runs to completion and returns the record.
  RunRecord finishedRun(const Scenario& scenario) {
    RunController controller;
    QSignalSpy finished(&controller, &RunController::finished);
    controller.start(scene_, scenario);
    if (!finished.wait(20000)) return {};
    return finished.takeFirst().at(0).value<RunRecord>();
  }

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void finishedRunDeliversResultsAndProgress() {
    RunController controller;
    QSignalSpy finished(&controller, &RunController::finished);
    QSignalSpy progress(&controller, &RunController::progressed);
    QSignalSpy partial(&controller, &RunController::partialResults);
    controller.setPartialInterval(0.05);
    QVERIFY(controller.start(scene_, rodScenario(0.6)) != 0);
    QVERIFY(controller.isRunning());
    // A second start while running is refused.
    QCOMPARE(controller.start(scene_, rodScenario(0.0)), quint64(0));
    QVERIFY(finished.wait(10000));
    QVERIFY(!controller.isRunning());
    const auto record = finished.takeFirst().at(0).value<RunRecord>();
    QVERIFY(record.results);
    QCOMPARE(record.results->findTable("profile")->rows(), std::size_t(50));
    QVERIFY(progress.count() >= 3);
    QCOMPARE(progress.last().at(0).toDouble(), 1.0);
    // Partial results stream while the run goes (0.6 s at >= 0.05 s intervals).
    QVERIFY2(partial.count() >= 2, qPrintable(QString::number(partial.count())));
  }

  void cancelStopsTheSolverWithin100ms() {
    RunController controller;
    QSignalSpy cancelled(&controller, &RunController::cancelled);
    QSignalSpy progress(&controller, &RunController::progressed);
    controller.start(scene_, rodScenario(5.0));
    QVERIFY(progress.wait(2000));
    controller.cancel();
    QVERIFY(cancelled.wait(2000));
    qInfo("cancel: solver stopped after %.2f ms, GUI thread heard after %.2f ms", controller.lastCancelLatency() * 1e3,
          controller.lastCancelAcknowledgeLatency() * 1e3);
    QVERIFY(controller.lastCancelLatency() >= 0.0);
    QVERIFY(controller.lastCancelLatency() < 0.1);
    QVERIFY(controller.lastCancelAcknowledgeLatency() < 0.1);
    QVERIFY(!controller.isRunning());
  }

  void failedRunReportsTheSolversWords() {
    RunController controller;
    QSignalSpy failed(&controller, &RunController::failed);
    controller.start(scene_, rodScenario(0.0, true));
    QVERIFY(failed.wait(10000));
    const QString message = failed.takeFirst().at(0).toString();
    QVERIFY2(message.contains(QStringLiteral("node 3 displacement")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("0.5")), qPrintable(message));
  }

  void invalidScenarioIsReportedNotRun() {
    RunController controller;
    QSignalSpy failed(&controller, &RunController::failed);
    Scenario bad = rodScenario(0.0);
    bad.parameters["geometry"]["length"] = -3.0;
    controller.start(scene_, bad);
    QVERIFY(failed.wait(10000));
    QVERIFY(failed.takeFirst().at(0).toString().contains(QStringLiteral("parameters.geometry.length")));
  }

  void destroyingTheControllerMidRunCancelsIt() {
    QElapsedTimer clock;
    {
      RunController controller;
      QSignalSpy progress(&controller, &RunController::progressed);
      controller.start(scene_, rodScenario(30.0));
      QVERIFY(progress.wait(2000));
      clock.start();
    }
    QVERIFY(clock.elapsed() < 500);
  }

  void historyLabelsRunsByWhatChanged() {
    RunHistory history(2);
    RunRecord a;
    a.id = 1;
    a.scenario = rodScenario(0.0);
    RunRecord b = a;
    b.id = 2;
    b.scenario.parameters["discretisation"]["point_count"] = 100;
    RunRecord c = b;
    c.id = 3;
    history.add(a);
    QCOMPARE(history.add(b).label, QStringLiteral("run 2 (point count = 100)"));
    QCOMPARE(history.add(c).label, QStringLiteral("run 3"));
    QCOMPARE(history.runs().size(), std::size_t(2));
    QVERIFY(!history.find(1));
    // With the scene's schema: the editor's label, 4 significant digits and the unit.
    RunRecord d = c;
    d.id = 4;
    d.scenario.parameters["geometry"]["length"] = 1.5707963267948966;
    QCOMPARE(history.add(d, false, &scene_.schema).label, QStringLiteral("run 4 (Length L = 1.571 m)"));
  }

  void plotsHoldTheExpectedPoints() {
    const RunRecord record = finishedRun(rodScenario(0.0));
    QVERIFY(record.results);
    PlotPanel panel;
    panel.resize(800, 600);
    panel.showResults(record.results, record.label);
    QCOMPARE(panel.count(), 2);
    QCOMPARE(panel.view(0)->pointCount(), 50);       // point_count
    QCOMPARE(panel.view(1)->pointCount(), 2 * 100);  // two columns × frame_count × 10 rows
    QCustomPlot* plot = panel.view(0)->plot();
    QCOMPARE(plot->xAxis->label(), QStringLiteral("Arc length [m]"));
    QCOMPARE(plot->yAxis->label(), QStringLiteral("Deflection [m]"));
    QCOMPARE(plot->graphCount(), 2);  // the curve and the reference points
    panel.view(0)->setLogY(true);
    QCOMPARE(plot->yAxis->scaleType(), QCPAxis::stLogarithmic);
  }

  // Two rising diagonals fill the bottom-left and top-right corners: the legend must take the top
  // left, where it covers no data point; the y label of several columns names the plot and unit.
  void legendGoesWhereItHidesNoData() {
    Results r;
    Table& t = r.tables.emplace_back();
    t.name = "lines";
    std::vector<double> x, y1, y2;
    for (int i = 0; i <= 100; ++i) {
      x.push_back(i);
      y1.push_back(i);
      y2.push_back(i + 5.0);
    }
    t.add("x", "m", x);
    t.add("low", "N", y1);
    t.add("high", "N", y2);
    PlotSpec spec;
    spec.name = spec.table = "lines";
    spec.title = "Two lines";
    spec.x = "x";
    spec.y = {"low", "high"};
    QCustomPlot plot;
    plot.resize(800, 600);
    QVERIFY(fillPlot(plot, r, spec));
    QCOMPARE(plot.yAxis->label(), QStringLiteral("Two lines [N]"));
    // A title's closing aside is left to the title: the axis label stays short enough for the axis.
    PlotSpec aside = spec;
    aside.title = "Two lines (curve: model, markers: measured)";
    QCustomPlot aside_plot;
    QVERIFY(fillPlot(aside_plot, r, aside));
    QCOMPARE(aside_plot.yAxis->label(), QStringLiteral("Two lines [N]"));
    QCPLayoutInset* inset = plot.axisRect()->insetLayout();
    QCOMPARE(inset->elementCount(), 1);
    QVERIFY(qobject_cast<QCPLegend*>(inset->elementAt(0)));
    QCOMPARE(inset->insetAlignment(0), Qt::AlignTop | Qt::AlignLeft);
  }

  // The dark theme redraws the plots on a dark background with light text, the light one on white.
  void plotsFollowTheTheme() {
    const RunRecord record = finishedRun(rodScenario(0.0));
    PlotView view(record.results->plots.front());
    view.resize(600, 400);
    view.setSources({{record.label, record.results}});
    applyTheme(Theme::Dark);
    QTRY_VERIFY(view.plot()->axisRect()->backgroundBrush().color().lightnessF() < 0.3);
    QVERIFY(view.plot()->xAxis->labelColor().lightnessF() > 0.7);
    const QImage dark = view.plot()->toPixmap(600, 400).toImage();
    applyTheme(Theme::Light);
    QTRY_COMPARE(view.plot()->axisRect()->backgroundBrush().color(), QColor(Qt::white));
    QVERIFY(view.plot()->xAxis->labelColor().lightnessF() < 0.3);
    applyTheme(Theme::System);
    // The picture itself: mostly dark pixels in the dark theme.
    long darkPixels = 0;
    for (int y = 0; y < dark.height(); y += 4)
      for (int x = 0; x < dark.width(); x += 4) darkPixels += dark.pixelColor(x, y).lightnessF() < 0.3;
    QVERIFY(darkPixels > 0.8 * (dark.width() / 4) * (dark.height() / 4));
  }

  // A zoom made during a run survives the live updates; an untouched plot follows the growing data;
  // a double-click fits again and later updates rescale once more.
  void userZoomSurvivesLiveUpdates() {
    PlotSpec spec;
    spec.name = spec.table = "line";
    spec.x = "x";
    spec.y = {"y"};
    PlotView zoomed(spec), untouched(spec);
    for (PlotView* v : {&zoomed, &untouched}) {
      v->resize(600, 400);
      v->show();
      v->setSources({{QStringLiteral("running"), growingLine(50)}});
    }
    QVERIFY(QTest::qWaitForWindowExposed(&zoomed));
    zoomed.plot()->replot();
    auto xRange = [](PlotView& v) { return v.plot()->axisRect()->axis(QCPAxis::atBottom)->range(); };
    auto yRange = [](PlotView& v) { return v.plot()->axisRect()->axis(QCPAxis::atLeft)->range(); };
    QCOMPARE(xRange(zoomed).upper, 49.0);  // fitted to the data: x = 0 … 49
    QVERIFY(!zoomed.keepsUserRange());

    // The user zooms in with the wheel over the middle of the axes.
    const QPointF centre = zoomed.plot()->axisRect()->rect().center();
    QWheelEvent wheel(centre, zoomed.plot()->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(zoomed.plot(), &wheel);
    const QCPRange x_zoom = xRange(zoomed), y_zoom = yRange(zoomed);
    QVERIFY2(x_zoom.size() < 0.95 * 49.0, qPrintable(QString::number(x_zoom.size())));
    QVERIFY(zoomed.keepsUserRange());

    // A live update with twice the data: the zoomed plot keeps its ranges exactly (same doubles),
    // the untouched one fits the new data (x up to 99, y up to 99² = 9801).
    for (PlotView* v : {&zoomed, &untouched}) v->setSources({{QStringLiteral("running"), growingLine(100)}});
    QCOMPARE(xRange(zoomed), x_zoom);
    QCOMPARE(yRange(zoomed), y_zoom);
    QCOMPARE(zoomed.pointCount(), 100);
    QCOMPARE(xRange(untouched).upper, 99.0);
    QCOMPARE(yRange(untouched).upper, 9801.0);

    // A double-click fits the axes to the data and gives the plot back to autoscaling.
    QMouseEvent click(QEvent::MouseButtonDblClick, centre, zoomed.plot()->mapToGlobal(centre), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(zoomed.plot(), &click);
    QVERIFY(!zoomed.keepsUserRange());
    QCOMPARE(xRange(zoomed).upper, 99.0);
    zoomed.setSources({{QStringLiteral("running"), growingLine(150)}});
    QCOMPARE(xRange(zoomed).upper, 149.0);
  }

  // Toolbar icons in the dark theme: their glyphs must stand out from the window colour (a
  // luminance difference of at least 0.4 of the full scale, about what black text on mid-grey
  // has); in the light theme the style's own icon is shown unchanged.
  void iconsStayReadableInTheDarkTheme() {
    for (QStyle::StandardPixmap which : {QStyle::SP_MediaPlay, QStyle::SP_MediaStop, QStyle::SP_MediaPause,
                                         QStyle::SP_BrowserReload}) {
      const QIcon icon = themedIcon(which);
      applyTheme(Theme::Dark);
      const QImage dark = icon.pixmap(32, 32).toImage();
      const QImage plain = QApplication::style()->standardIcon(which).pixmap(32, 32).toImage();
      const double window = qGray(QApplication::palette().color(QPalette::Window).rgb()) / 255.0;
      const double themed = glyphLuminance(dark);
      qInfo("icon %d on the dark window (luminance %.2f): style's own %.2f, themed %.2f", int(which), window,
            glyphLuminance(plain), themed);
      QVERIFY2(std::abs(themed - window) > 0.4, qPrintable(QString::number(themed)));
      applyTheme(Theme::Light);
      QCOMPARE(icon.pixmap(32, 32).toImage(), QApplication::style()->standardIcon(which).pixmap(32, 32).toImage());
    }
    applyTheme(Theme::System);
  }

  void hoverShowsTheNearestValue() {
    const RunRecord record = finishedRun(rodScenario(0.0));
    PlotView view(record.results->plots.front());
    view.resize(800, 600);
    view.show();
    view.setSources({{record.label, record.results}});
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.plot()->replot();
    QCPGraph* graph = view.plot()->graph(0);
    const double key = graph->data()->at(10)->key, value = graph->data()->at(10)->value;
    const QPoint at(static_cast<int>(graph->keyAxis()->coordToPixel(key)),
                    static_cast<int>(graph->valueAxis()->coordToPixel(value)));
    QMouseEvent move(QEvent::MouseMove, at, view.plot()->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(view.plot(), &move);
    QVERIFY2(view.readout().contains(QStringLiteral("Arc length [m] = %1").arg(key, 0, 'g', 6)), qPrintable(view.readout()));
  }

  void everyExportFormatWritesAValidFile() {
    const RunRecord record = finishedRun(rodScenario(0.0));
    PlotView view(record.results->plots.front());
    view.resize(800, 600);
    view.setSources({{record.label, record.results}});
    QTemporaryDir dir;
    const QString png = dir.filePath(QStringLiteral("p.png")), pdf = dir.filePath(QStringLiteral("p.pdf")),
                  svg = dir.filePath(QStringLiteral("p.svg")), csv = dir.filePath(QStringLiteral("p.csv"));
    for (const QString& f : {png, pdf, svg, csv}) view.exportTo(f, 900, 600);
    const QImage image(png);
    QCOMPARE(image.size(), QSize(900, 600));
    QVERIFY(test::distinctColours(image) >= 8);
    QVERIFY(test::saturatedFraction(image) > 0.001);  // the blue curve is there
    QFile pdf_file(pdf);
    QVERIFY(pdf_file.open(QIODevice::ReadOnly));
    QCOMPARE(pdf_file.read(4), QByteArray("%PDF"));
    QFile svg_file(svg);
    QVERIFY(svg_file.open(QIODevice::ReadOnly));
    QVERIFY(svg_file.readAll().contains("<svg"));
    const auto rows = test::readCsv(csv);
    QCOMPARE(rows.size(), std::size_t(2 + 50));
    QCOMPARE(rows[0], (std::vector<std::string>{"arc_length", "deflection"}));
    QCOMPARE(rows[1], (std::vector<std::string>{"m", "m"}));
    QCOMPARE(std::stod(rows.back()[0]), 100.0);
    // No temporary files are left behind.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 4);
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, view.exportTo(dir.filePath(QStringLiteral("p.xyz"))));
  }

  void reportFolderHasEveryFile() {
    const RunRecord record = finishedRun(rodScenario(0.0));
    QTemporaryDir dir;
    const auto files = writeReportFolder(dir.path().toStdString(), record.scenario, *record.results, record.started_at);
    for (const char* name : {"scenario.json", "summary.json", "summary.md", "profile.csv", "history.csv",
                             "reference.csv", "deflection.png", "deflection.pdf", "tip_motion.png", "tip_motion.pdf"})
      QVERIFY2(QFileInfo::exists(dir.filePath(QString::fromLatin1(name))), name);
    QCOMPARE(files.size(), std::size_t(10));
    QFile md(dir.filePath(QStringLiteral("summary.md")));
    QVERIFY(md.open(QIODevice::ReadOnly));
    QVERIFY(md.readAll().contains("| max_deflection |"));
    // summary.json says which Maris ran the run and when, as the CLI's does (the same writeRunFolder).
    const Json summary = Json::parse(readTextFile(dir.filePath(QStringLiteral("summary.json")).toStdString()));
    QCOMPARE(summary["maris_version"].get<std::string>(), projectVersion());
    QCOMPARE(summary["commit"].get<std::string>(), commitId());
    QVERIFY(summary["started_at"].is_string());
    QVERIFY(record.started_at > std::chrono::system_clock::now() - std::chrono::minutes(1));
    QCOMPARE(summary["host_threads"].get<unsigned>(), std::thread::hardware_concurrency());
  }
};

QTEST_MAIN(RunTest)
#include "test_run.moc"
