// Live plots of real scenes: the riser publishes partial results while it integrates, the FIV sweep
// its table so far, and the plot tabs fed by them (wired as in the main window) grow before the run
// finishes. Offscreen platform.
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QtTest>

#include <algorithm>

#include "catalog.hpp"
#include "plots/plot_panel.hpp"
#include "run/run_controller.hpp"
#include "ui_test_support.hpp"

using namespace maris;
using namespace maris::ui;

class LiveTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void riserPlotsGrowWhileTheRunGoes() {
    const SceneDefinition* scene = findScene("riser");
    if (!scene) QSKIP("this build has no riser scene");
    const BuiltinScenario* example = findBuiltin("riser_default");
    QVERIFY(example);
    // The default riser, shortened: a few seconds of simulated time, few frames, no profiles.
    Scenario scenario = example->scenario;
    scenario.parameters["solver"]["end_time"] = 2.0;
    scenario.parameters["output"]["frame_count"] = 4;
    scenario.parameters["output"]["stress_times"] = Json::array();

    RunController controller;
    controller.setPartialInterval(0.05);
    PlotPanel plots;
    plots.resize(800, 600);
    plots.show();  // so the current tab really paints
    std::vector<int> live_points;  // points of the probe plot after each partial update
    std::vector<double> live_end_times;
    double slowest_update_ms = 0.0;
    QObject::connect(&controller, &RunController::partialResults, &plots, [&](ResultsPtr partial) {
      QElapsedTimer clock;
      clock.start();
      plots.showResults(partial, QStringLiteral("running"));
      slowest_update_ms = std::max(slowest_update_ms, clock.nsecsElapsed() * 1e-6);
      for (int i = 0; i < plots.count(); ++i)
        if (plots.view(i)->spec().name == "probe_displacement") live_points.push_back(plots.view(i)->pointCount());
      live_end_times.push_back(partial->findTable("history")->columns.front().values.back());
    });
    // A 5 ms heartbeat in the GUI thread: its longest gap is the longest the GUI thread was blocked
    // (plot updates and their queued replots). Reported, not a pass/fail criterion (machine-dependent).
    QTimer heartbeat;
    QElapsedTimer since_beat;
    double longest_gap_ms = 0.0;
    heartbeat.setInterval(5);
    QObject::connect(&heartbeat, &QTimer::timeout, [&] {
      if (since_beat.isValid()) longest_gap_ms = std::max(longest_gap_ms, since_beat.nsecsElapsed() * 1e-6);
      since_beat.start();
    });
    QSignalSpy finished(&controller, &RunController::finished);
    QVERIFY(controller.start(*scene, scenario) != 0);
    heartbeat.start();
    QVERIFY(finished.wait(120000));
    heartbeat.stop();
    const RunRecord record = finished.takeFirst().at(0).value<RunRecord>();
    qInfo("%zu partial updates; slowest plot update %.1f ms; longest GUI-thread gap %.1f ms", live_points.size(),
          slowest_update_ms, longest_gap_ms);

    // At least two live updates, each drawing more of the history than the one before, all before the end.
    QVERIFY2(live_points.size() >= 2, qPrintable(QString::number(live_points.size())));
    QVERIFY(std::is_sorted(live_points.begin(), live_points.end()));
    QVERIFY(live_points.back() > live_points.front());
    QVERIFY(std::is_sorted(live_end_times.begin(), live_end_times.end()));
    QVERIFY(live_end_times.front() < 2.0);
    // The probe plot draws three columns (dx, dy, dz) of the history rows.
    const std::size_t final_rows = record.results->findTable("history")->rows();
    QVERIFY(static_cast<std::size_t>(live_points.front()) < 3 * final_rows);

    // The finished run replaces the live one on the same tab, with every row.
    plots.showResults(record.results, record.label);
    for (int i = 0; i < plots.count(); ++i)
      if (plots.view(i)->spec().name == "probe_displacement")
        QCOMPARE(plots.view(i)->pointCount(), static_cast<int>(3 * final_rows));
  }

  // A sweep scene: the FIV sweep publishes its table so far, so the amplitude plot gains points
  // from update to update before the run ends, and the finished run has at least as many.
  void fivSweepPlotGrowsWhileTheRunGoes() {
    const SceneDefinition* scene = findScene("fiv");
    if (!scene) QSKIP("this build has no fiv scene");
    Scenario scenario = findBuiltin("fiv_default")->scenario;
    scenario.parameters["sweep"]["speed_count"] = 20;
    RunController controller;
    controller.setPartialInterval(0.01);
    PlotPanel plots;
    plots.resize(800, 600);
    plots.show();
    std::vector<int> live_points;  // points of the amplitude plot after each partial update
    QObject::connect(&controller, &RunController::partialResults, &plots, [&](ResultsPtr partial) {
      plots.showResults(partial, QStringLiteral("running"));
      for (int i = 0; i < plots.count(); ++i)
        if (plots.view(i)->spec().name == "amplitude_ratio") live_points.push_back(plots.view(i)->pointCount());
    });
    QSignalSpy finished(&controller, &RunController::finished);
    QVERIFY(controller.start(*scene, scenario) != 0);
    QVERIFY(finished.wait(120000));
    const RunRecord record = finished.takeFirst().at(0).value<RunRecord>();
    QString counts;
    for (int n : live_points) counts += QString::number(n) + QLatin1Char(' ');
    qInfo("amplitude plot points after each partial update: %s", qPrintable(counts));
    QVERIFY2(live_points.size() >= 2, qPrintable(counts));
    QVERIFY(std::is_sorted(live_points.begin(), live_points.end()));
    QVERIFY(live_points.back() > live_points.front());
    plots.showResults(record.results, record.label);
    for (int i = 0; i < plots.count(); ++i)
      if (plots.view(i)->spec().name == "amplitude_ratio") QVERIFY(plots.view(i)->pointCount() >= live_points.back());
  }
};

QTEST_MAIN(LiveTest)
#include "test_live.moc"
