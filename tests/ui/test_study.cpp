// Studies in the GUI, off-screen: a sweep started from the parameter editor's context menu runs its
// cases on the worker pool, plots every case (values equal to the same cases run one at a time
// through the single-run controller, and to the test scene's closed form pi r^2 L), opens a
// clicked case in the results view, writes study.csv and the plot; two parameters give a line per
// value and a heat map; Cancel stops the pool; a study file saves and reopens; a study with a bad
// case runs nothing; a load-case table runs its rows; a Latin hypercube built in its dialog samples
// every stratum; a table cell is added, edited, saved and reopened as a parameter; a table study's weighted
// sum shows in the dock (the hand-computed sum, the cases it still waits for).
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QPlainTextEdit>
#include <QRadioButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QTableWidget>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QMenu>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/run_output.hpp"
#include "run/run_panel.hpp"
#include "plots/result_plot.hpp"
#include "plots/plot_panel.hpp"
#include "plots/plot_view.hpp"
#include "view3d/scene_view.hpp"
#include "document/scenario_document.hpp"
#include "editor/parameter_editor.hpp"
#include "editor/table_editor.hpp"
#include "main_window.hpp"
#include "plots/display_units.hpp"
#include "plots/study_plot.hpp"
#include "run/run_controller.hpp"
#include "run/run_history.hpp"
#include "run/results_summary.hpp"
#include "study/add_parameter_dialog.hpp"
#include "study/latin_hypercube_dialog.hpp"
#include "study/study_panel.hpp"
#include "study/study_plot_view.hpp"
#include "study/study.hpp"
#include "study/study_folder.hpp"
#include "study/study_runner.hpp"
#include "study/sweep_dialog.hpp"
#include "study/weighted_sum_dialog.hpp"
#include "test_scene.hpp"
#include "ui_test_support.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

int columnOf(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  return -1;
}

// The sweep prompt of the panel, answered without a dialog.
StudyPanel::SweepPrompt answer(SweepRange range, bool add_only = false) {
  return [range, add_only](const ParamSpec& spec, const SweepRange&) -> std::optional<std::pair<SweepRange, bool>> {
    SweepRange r = range;
    r.path = spec.path;
    return std::make_pair(r, add_only);
  };
}

// Chooses "Sweep this parameter…" in the field's context menu, as a user would.
bool chooseSweep(ParameterEditor* editor, const std::string& path) {
  std::unique_ptr<QMenu> menu(editor->fieldMenu(path));
  if (!menu) return false;
  for (QAction* a : menu->actions())
    if (a->objectName() == QLatin1String("sweepAction")) {
      a->trigger();
      return true;
    }
  return false;
}

const double kPi = 3.14159265358979323846;

}  // namespace

class StudyTest : public QObject {
  Q_OBJECT

  std::unique_ptr<MainWindow> window_;
  StudyPanel* panel() const { return window_->study(); }

  bool runAndWait(int timeout_ms = 60000) {
    QSignalSpy finished(panel(), &StudyPanel::studyFinished);
    if (!panel()->isRunning() && finished.isEmpty()) return false;
    return finished.wait(timeout_ms);
  }

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void init() {
    window_ = std::make_unique<MainWindow>(test::rodLibrary());
    window_->resize(1400, 900);
    window_->show();
    panel()->setThreads(2);
  }
  void cleanup() { window_.reset(); }

  void sweepFromTheEditorPlotsTheSingleRunsValuesAndWritesTheCsv() {
    panel()->setSweepPrompt(answer({"", 50.0, 150.0, 5, false}));
    QSignalSpy finished(panel(), &StudyPanel::studyFinished);
    QVERIFY(chooseSweep(window_->editor(), "geometry.length"));
    QVERIFY(panel()->isRunning());
    QVERIFY(!window_->runAction()->isEnabled());  // one thing at a time on the cores
    QVERIFY(window_->cancelAction()->isEnabled());
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.first().at(0).toInt(), 5);
    QCOMPARE(finished.first().at(1).toInt(), 0);

    StudyPlotView* view = panel()->plotView();
    const int r = view->resultBox()->findData(QStringLiteral("rod_volume"));
    QVERIFY(r >= 0);
    view->resultBox()->setCurrentIndex(r);
    QVERIFY(view->hasData());
    QCOMPARE(view->drawn().points, 5);
    QCOMPARE(view->plot()->graphCount(), 1);
    QCOMPARE(view->plot()->xAxis->label(), QStringLiteral("Length L [m]"));
    QCOMPARE(view->plot()->yAxis->label(), QStringLiteral("Rod volume [m³]"));

    // Each point equals the same case run alone through the single-run controller (bitwise), and
    // the closed form pi r^2 L (r = 0.5 m) to 1e-12 relative.
    QCPGraph* graph = view->plot()->graph(0);
    const Scenario base = window_->document()->scenario();
    for (int k = 0; k < 5; ++k) {
      const double length = 50.0 + 25.0 * k;
      const auto point = graph->data()->at(k);
      QVERIFY(std::abs(point->key - length) <= 1e-12 * length);
      const double length_run = point->key;  // the case's own value, as the engine expanded it
      Scenario alone = base;
      alone.parameters["geometry"]["length"] = length_run;
      RunController controller;
      QSignalSpy done(&controller, &RunController::finished);
      controller.start(*window_->document()->scene(), alone);
      QVERIFY(done.wait(20000));
      const double single = done.first().at(0).value<RunRecord>().results->findScalar("rod_volume")->value;
      QCOMPARE(point->value, single);
      QVERIFY(std::abs(point->value - kPi * 0.25 * length) <= 1e-12 * point->value);
    }

    // Clicking the third point opens that case in the results view.
    const QPointF at = studyCasePixel(*view->plot(), view->drawn(), 2);
    QVERIFY(at.x() >= 0);
    QTest::mouseClick(view->plot(), Qt::LeftButton, {}, at.toPoint());
    const RunRecord* shown = window_->history().latest();
    QVERIFY(shown);
    QVERIFY2(shown->label.startsWith(QStringLiteral("study case 0003")), qPrintable(shown->label));
    QCOMPARE(shown->scenario.parameters["geometry"]["length"].get<double>(), graph->data()->at(2)->key);
    QCOMPARE(shown->results->findScalar("rod_volume")->value, graph->data()->at(2)->value);
    test::keepScreenshot(window_->grab().toImage(), QStringLiteral("study_window"));

    // study.csv: one row per case with the varied parameter and every scalar.
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("study.csv"));
    QVERIFY(panel()->exportCsv(csv));
    const auto rows = test::readCsv(csv);
    QVERIFY(!rows.empty());
    const int length_col = columnOf(rows[0], "geometry.length");
    const int volume_col = columnOf(rows[0], "rod_volume");
    QVERIFY2(length_col >= 0 && volume_col >= 0, rows[0].empty() ? "" : rows[0].front().c_str());
    int data_rows = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
      char* end = nullptr;
      const double length = std::strtod(rows[i][length_col].c_str(), &end);
      if (end == rows[i][length_col].c_str()) continue;  // the units row
      ++data_rows;
      const double volume = std::strtod(rows[i][volume_col].c_str(), nullptr);
      QVERIFY(std::abs(volume - kPi * 0.25 * length) <= 1e-12 * volume);
    }
    QCOMPARE(data_rows, 5);
    // The plot as PNG and SVG through the plot export.
    const QString png = dir.filePath(QStringLiteral("study.png"));
    QVERIFY(panel()->exportPlot(png));
    QImage image(png);
    QCOMPARE(image.size(), QSize(1200, 800));
    QVERIFY(test::distinctColours(image) > 4);
    test::keepScreenshot(image, QStringLiteral("study_lines"));
    const QString svg = dir.filePath(QStringLiteral("study.svg"));
    QVERIFY(panel()->exportPlot(svg));
    QFile svg_file(svg);
    QVERIFY(svg_file.open(QIODevice::ReadOnly));
    QVERIFY(svg_file.readAll().contains("<svg"));
  }

  void sweepDialogProposesAndChecksTheRange() {
    const ParamSpec* spec = window_->document()->scene()->schema.find("geometry.length");
    const SweepRange proposed = proposedSweep(*spec, window_->document()->value("geometry.length"));
    QCOMPARE(proposed.from, 50.0);  // half and one and a half times 100 m
    QCOMPARE(proposed.to, 150.0);
    QCOMPARE(proposed.count, 5);
    SweepDialog dialog(*spec, proposed, window_.get());
    dialog.show();
    QVERIFY(dialog.sweepButton()->isEnabled());
    dialog.fromEdit()->setText(QStringLiteral("-1"));
    QVERIFY(!dialog.sweepButton()->isEnabled());
    QVERIFY2(dialog.problemLabel()->text().startsWith(QStringLiteral("from: must be in (0, 1000]")),
             qPrintable(dialog.problemLabel()->text()));
    dialog.fromEdit()->setText(QStringLiteral("10"));
    dialog.spacingBox()->setCurrentIndex(1);
    QVERIFY(dialog.sweepButton()->isEnabled());
    QCOMPARE(dialog.range(), (SweepRange{"geometry.length", 10.0, 150.0, 5, true}));
    test::keepScreenshot(dialog.grab().toImage(), QStringLiteral("study_sweep_dialog"));
    // An integer field: whole numbers, no more values than there are between the ends.
    const ParamSpec* points = window_->document()->scene()->schema.find("discretisation.point_count");
    QVERIFY(sweepProblem(*points, {"discretisation.point_count", 2.0, 4.0, 5, false}).contains(QStringLiteral("at most 3")));
    QVERIFY(sweepProblem(*points, {"discretisation.point_count", 2.0, 4.0, 3, false}).isEmpty());
  }

  void twoParametersGiveALinePerValueAndAHeatMap() {
    panel()->setSweepPrompt(answer({"", 2.0, 3.0, 2, false}, true));
    QVERIFY(chooseSweep(window_->editor(), "geometry.radius"));
    panel()->setSweepPrompt(answer({"", 10.0, 1000.0, 3, true}, true));
    QVERIFY(chooseSweep(window_->editor(), "geometry.length"));
    QCOMPARE(panel()->parameters().size(), std::size_t(2));
    QVERIFY(!panel()->isRunning());  // "Add to study" does not run
    QVERIFY(panel()->startStudy());
    QVERIFY(runAndWait());
    StudyPlotView* view = panel()->plotView();
    view->resultBox()->setCurrentIndex(view->resultBox()->findData(QStringLiteral("rod_volume")));
    view->againstBox()->setCurrentIndex(view->againstBox()->findData(QStringLiteral("geometry.length")));  // a line per radius
    QCOMPARE(view->plot()->graphCount(), 2);
    QCOMPARE(view->drawn().points, 6);
    QCOMPARE(view->plot()->xAxis->scaleType(), QCPAxis::stLogarithmic);  // log spacing: log axis
    QVERIFY(std::abs(view->plot()->graph(0)->data()->at(1)->key - 100.0) < 1e-12);  // 10, 100, 1000
    QCOMPARE(view->plot()->graph(0)->name(), QStringLiteral("Radius r [m] = 2"));
    QVERIFY(view->kindBox()->isEnabled());
    view->kindBox()->setCurrentIndex(1);
    QCOMPARE(view->drawn().kind, StudyPlotKind::HeatMap);
    QCOMPARE(view->drawn().points, 6);
    auto* map = qobject_cast<QCPColorMap*>(view->plot()->plottable(0));
    QVERIFY(map);
    // Cell (length 1000, radius 3): pi r^2 L.
    QVERIFY(std::abs(map->data()->cell(2, 1) - kPi * 9.0 * 1000.0) <= 1e-12 * kPi * 9.0 * 1000.0);
    test::keepScreenshot(window_->grab().toImage(), QStringLiteral("study_heat_map"));
    const QPointF cell = studyCasePixel(*view->plot(), view->drawn(), 5);
    QCOMPARE(studyCaseAt(*view->plot(), view->drawn(), cell), 5);
  }

  // Legend entries give a parameter's value to 4 significant digits ("1.01e+11 Pa", not 1.00957e+11), more only
  // where two of the study's values would then read the same (1.00001 and 1.00002 keep 6).
  void legendValuesHaveFourDigitsUnlessMoreTellThemApart() {
    StudyPlotData data;
    data.result_name = "bending_stress_max";
    data.result_unit = "Pa";
    data.parameters = {{"geometry.length", "Length L", "m", false, {10.0, 20.0, 10.0, 20.0}},
                       {"section.youngs_modulus", "Young's modulus E", "Pa", false, {7e10, 7e10, 1.00957e11, 1.00957e11}}};
    data.result = {2.0e7, 4.0e7, 1.0e7, 3.0e7};
    QCustomPlot plot;
    plot.resize(600, 400);
    QVERIFY(fillStudyPlot(plot, data, 0, StudyPlotKind::Lines));
    QStringList names;
    for (int g = 0; g < plot.graphCount(); ++g) names << plot.graph(g)->name();
    QVERIFY2(names.contains(QStringLiteral("Young's modulus E [Pa] = 1.01e+11")), qPrintable(names.join(" | ")));
    data.parameters[1].values = {1.00001, 1.00001, 1.00002, 1.00002};
    data.parameters[1].unit = "-";
    QVERIFY(fillStudyPlot(plot, data, 0, StudyPlotKind::Lines));
    names.clear();
    for (int g = 0; g < plot.graphCount(); ++g) names << plot.graph(g)->name();
    QVERIFY2(names.contains(QStringLiteral("Young's modulus E = 1.00001")) &&
                 names.contains(QStringLiteral("Young's modulus E = 1.00002")),
             qPrintable(names.join(" | ")));
  }

  // View ▸ Units reaches the study plot: lengths chosen in mm and stresses in MPa scale the drawn values (SI × 1000
  // and × 1e-6, exactly) and name the unit on the axes, the legend and the colour scale; the data stay SI.
  void displayUnitsReachTheStudyPlot() {
    StudyPlotData data;
    data.result_name = "bending_stress_max";
    data.result_label = "σ_b max";
    data.result_unit = "Pa";
    data.parameters = {{"geometry.length", "Length L", "m", false, {10.0, 20.0, 10.0, 20.0}},
                       {"geometry.radius", "", "m", false, {0.5, 0.5, 0.25, 0.25}}};
    data.result = {2.0e7, 4.0e7, 1.0e7, 3.0e7};
    setDisplayUnit("m", "mm");
    setDisplayUnit("Pa", "MPa");
    QCustomPlot plot;
    plot.resize(600, 400);
    QVERIFY(fillStudyPlot(plot, data, 0, StudyPlotKind::Lines));
    QCOMPARE(plot.axisRect()->axis(QCPAxis::atBottom)->label(), QStringLiteral("Length L [mm]"));
    QCOMPARE(plot.axisRect()->axis(QCPAxis::atLeft)->label(), QStringLiteral("σ_b max [MPa]"));
    QCOMPARE(plot.graphCount(), 2);  // a line per radius, named in mm
    QCOMPARE(plot.graph(0)->name(), QStringLiteral("geometry.radius [mm] = 250"));  // no label: the path
    QCOMPARE(plot.graph(0)->data()->at(1)->key, 20000.0);
    QCOMPARE(plot.graph(0)->data()->at(1)->value, 30.0);
    QVERIFY(fillStudyPlot(plot, data, 0, StudyPlotKind::HeatMap));
    auto* map = qobject_cast<QCPColorMap*>(plot.plottable(0));
    QVERIFY(map);
    QCOMPARE(map->data()->cell(1, 1), 40.0);  // length 20 m, radius 0.5 m
    QCOMPARE(map->colorScale()->axis()->label(), QStringLiteral("σ_b max [MPa]"));
    auto ticker = plot.axisRect()->axis(QCPAxis::atBottom)->ticker().dynamicCast<QCPAxisTickerText>();
    QVERIFY(ticker);
    QCOMPARE(ticker->ticks().value(1), QStringLiteral("20000"));  // 20 m in mm
    QCOMPARE(data.result.front(), 2.0e7);                         // the numbers themselves stay SI
    setDisplayUnit("m", "m");
    setDisplayUnit("Pa", "Pa");
    QVERIFY(fillStudyPlot(plot, data, 0, StudyPlotKind::Lines));
    QCOMPARE(plot.axisRect()->axis(QCPAxis::atLeft)->label(), QStringLiteral("σ_b max [Pa]"));
    QCOMPARE(plot.graph(0)->data()->at(1)->value, 3.0e7);
  }

  void cancelStopsThePoolQuickly() {
    window_->document()->edit("run.delay", Json(5.0));
    panel()->setSweepPrompt(answer({"", 50.0, 120.0, 8, false}));
    QSignalSpy cancelled(panel(), &StudyPanel::studyCancelled);
    QSignalSpy progress(panel()->runner(), &StudyRunner::progressed);
    QVERIFY(panel()->sweep(QStringLiteral("geometry.length")));
    QTRY_VERIFY_WITH_TIMEOUT(progress.count() >= 3, 10000);
    QElapsedTimer clock;
    clock.start();
    window_->cancelAction()->trigger();  // Esc, as for a single run
    QVERIFY(cancelled.wait(5000));
    qInfo("study cancel: workers stopped %.1f ms after the request, GUI heard after %lld ms",
          panel()->runner()->lastCancelLatency() * 1e3, static_cast<long long>(clock.elapsed()));
    QVERIFY(panel()->runner()->lastCancelLatency() < 1.0);
    QVERIFY(!panel()->isRunning());
    QVERIFY(window_->runAction()->isEnabled());
    int cancelled_cases = 0;
    for (int i = 0; i < panel()->session().caseCount(); ++i)
      if (panel()->session().outcome(i).status == StudySession::Status::Cancelled) ++cancelled_cases;
    QCOMPARE(cancelled_cases, 8);  // 5 s each: none finished
  }

  void aStudySavesAndReopens() {
    panel()->setSweepPrompt(answer({"", 0.2, 0.8, 4, false}, true));
    QVERIFY(panel()->sweep(QStringLiteral("geometry.radius")));
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("radius.study.json"));
    QVERIFY2(panel()->saveStudy(file), qPrintable(panel()->lastError()));
    const Scenario base = window_->document()->scenario();
    // The editor moves on; the reopened study keeps its own base and grid.
    window_->document()->edit("geometry.length", Json(300.0));
    panel()->clearParameters();
    QVERIFY2(panel()->openStudy(file), qPrintable(panel()->lastError()));
    QCOMPARE(panel()->parameters().size(), std::size_t(1));
    QCOMPARE(panel()->parameters()[0].path, std::string("geometry.radius"));
    QCOMPARE(panel()->parameters()[0].count, 4);
    QCOMPARE(panel()->session().base().parameters, base.parameters);
    QVERIFY(panel()->startStudy());
    QVERIFY(runAndWait());
    const StudyPlotData data = panel()->session().plotData("rod_volume");
    QCOMPARE(data.caseCount(), std::size_t(4));
    for (std::size_t c = 0; c < 4; ++c) {
      const double radius = data.parameters[0].values[c];
      QVERIFY(std::abs(data.result[c] - kPi * radius * radius * 100.0) <= 1e-12 * data.result[c]);
    }
  }

  // A load-case table (one column per parameter path, one row per case) over the open scenario runs
  // its rows; each case's volume is pi r^2 L of its own row (closed form), and study.csv lists them.
  void aLoadCaseTableRunsItsRows() {
    QTemporaryDir dir;
    const QString table = dir.filePath(QStringLiteral("cases.csv"));
    QFile file(table);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("geometry.length,geometry.radius\n120,0.3\n80,0.2\n150,0.5\n");
    file.close();
    QVERIFY2(panel()->openCaseTable(table), qPrintable(panel()->lastError()));
    QCOMPARE(panel()->session().kindName(), QStringLiteral("table"));
    // The table is the design: no grid parameter is added to it (that would replace it by a grid over its base),
    // and the empty grid table is hidden.
    QVERIFY(panel()->parameterTable()->isHidden());
    bool asked = false;
    panel()->setParameterPrompt([&asked](const SceneDefinition&, const Json&, const std::vector<std::string>&) {
      asked = true;
      return std::string("geometry.radius");
    });
    QVERIFY(!panel()->addParameterDialog());
    QVERIFY(!asked);
    panel()->setSweepPrompt(answer({"", 0.2, 0.8, 4, false}, true));
    QVERIFY(!panel()->sweep(QStringLiteral("geometry.radius")));
    QVERIFY2(panel()->lastError().contains(QStringLiteral("cannot be added")), qPrintable(panel()->lastError()));
    QCOMPARE(panel()->session().kindName(), QStringLiteral("table"));
    QVERIFY(panel()->startStudy());
    QVERIFY(runAndWait());
    const StudyPlotData data = panel()->session().plotData("rod_volume");
    QCOMPARE(data.caseCount(), std::size_t(3));
    const double rows[3][2] = {{120, 0.3}, {80, 0.2}, {150, 0.5}};
    for (std::size_t c = 0; c < 3; ++c) {
      const double expected = kPi * rows[c][1] * rows[c][1] * rows[c][0];
      QVERIFY(std::abs(data.result[c] - expected) <= 1e-12 * expected);
    }
    const QString csv = dir.filePath(QStringLiteral("study.csv"));
    QVERIFY(panel()->exportCsv(csv));
    const auto lines = test::readCsv(csv);
    QCOMPARE(lines.size(), std::size_t(5));  // names, units, three cases
    QCOMPARE(lines[4][1], std::string("ok"));
    // A bad table is refused with the field named.
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("geometry.lenght\n120\n");
    file.close();
    QVERIFY(!panel()->openCaseTable(table));
    QVERIFY2(panel()->lastError().contains(QStringLiteral("geometry.lenght")), qPrintable(panel()->lastError()));
  }

  // A Latin hypercube built in its dialog over the open scenario (the engine draws the cases): 8 cases,
  // each parameter inside its interval with exactly one case in each of its 8 equal strata (the design's
  // definition); each case's volume is pi r^2 L of its own values (closed form, 1e-12 relative); the same
  // seed gives the same cases (bitwise). Defaults are half to one and a half times the scenario's value.
  void aLatinHypercubeFromItsDialogSamplesEveryStratum() {
    const ScenarioDocument* document = window_->document();
    LatinHypercubeDialog dialog(*document->scene(), document->scenario());
    QVERIFY(!dialog.createButton()->isEnabled());  // nothing ticked yet
    // geometry.length is 100 m (allowed in (0, 1000] m): proposed 50 to 150 m, not the allowed range.
    // Rows show the parameter's label (the path is in the tooltip), never the raw path.
    const ParamSpec* length = nullptr;
    for (const ParamSpec& spec : document->scene()->schema.fields)
      if (spec.path == "geometry.length") length = &spec;
    QVERIFY(length);
    const auto rows = dialog.table()->findItems(QString::fromStdString(parameterLabel(*length)) + QStringLiteral(" [m]"), Qt::MatchExactly);
    QCOMPARE(rows.size(), 1);
    QCOMPARE(dialog.table()->item(rows.first()->row(), 1)->text(), QStringLiteral("50"));
    QCOMPARE(dialog.table()->item(rows.first()->row(), 2)->text(), QStringLiteral("150"));
    QVERIFY(dialog.choose("geometry.length", -5.0, 150.0));
    QVERIFY(!dialog.createButton()->isEnabled());
    QVERIFY2(dialog.problem().startsWith(QString::fromStdString(parameterLabel(*length)) + QStringLiteral(": from")), qPrintable(dialog.problem()));
    const double bounds[2][2] = {{50.0, 150.0}, {0.2, 0.6}};  // length, radius (the design's path order)
    QVERIFY(dialog.choose("geometry.length", bounds[0][0], bounds[0][1]));
    QVERIFY(dialog.choose("geometry.radius", bounds[1][0], bounds[1][1]));
    const int n = 8;
    dialog.samplesBox()->setValue(n);
    dialog.seedBox()->setValue(42);
    QVERIFY2(dialog.createButton()->isEnabled(), qPrintable(dialog.problem()));
    const LatinHypercubeDesign design = dialog.design();
    QCOMPARE(design.ranges.size(), std::size_t(2));

    QVERIFY2(panel()->defineLatinHypercube(design), qPrintable(panel()->lastError()));
    QCOMPARE(panel()->session().kindName(), QStringLiteral("latin hypercube"));
    QVERIFY(panel()->startStudy());
    QVERIFY(runAndWait());
    const StudyPlotData data = panel()->session().plotData("rod_volume");
    QCOMPARE(data.caseCount(), std::size_t(n));
    QCOMPARE(data.parameters.size(), std::size_t(2));
    QCOMPARE(data.parameters[0].name, std::string("geometry.length"));
    QCOMPARE(data.parameters[1].name, std::string("geometry.radius"));
    for (std::size_t p = 0; p < 2; ++p) {
      const double low = bounds[p][0], high = bounds[p][1];
      std::vector<int> per_stratum(n, 0);
      for (double v : data.parameters[p].values) {
        QVERIFY(v >= low && v <= high);
        ++per_stratum[std::min(n - 1, static_cast<int>(std::floor((v - low) / (high - low) * n)))];
      }
      for (int k = 0; k < n; ++k) QCOMPARE(per_stratum[k], 1);
    }
    for (std::size_t c = 0; c < data.caseCount(); ++c) {
      const double length = data.parameters[0].values[c], radius = data.parameters[1].values[c];
      const double expected = kPi * radius * radius * length;
      QVERIFY(std::abs(data.result[c] - expected) <= 1e-12 * expected);
    }
    StudySession again;
    again.defineLatinHypercube(*document->scene(), document->scenario(), design);
    again.expand();
    QCOMPARE(again.caseCount(), n);
    for (int c = 0; c < n; ++c)
      QVERIFY(again.caseScenario(c).parameters == panel()->session().caseScenario(c).parameters);

    if (const QByteArray shots = qgetenv("MARIS_UI_SCREENSHOT_DIR"); !shots.isEmpty()) {  // for the docs
      dialog.resize(720, 520);
      dialog.show();
      QTest::qWait(200);
      dialog.grab().save(QDir(QString::fromLocal8Bit(shots)).filePath(QStringLiteral("latin_hypercube_dialog.png")));
    }
  }

  void theSweepDialogStaysOpenOnARangeWithInvalidCasesAndSaysWhy() {
    // The radius must stay below half the length: with r = 5 m a length of 5 m breaks the scene's cross-field
    // check although the length field allows it. The real dialog (the panel's own prompt) is answered below.
    window_->document()->edit("geometry.radius", Json(5.0));
    QString shown;
    bool stayed_open = false;
    auto sweepDialog = [] {
      for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* d = qobject_cast<SweepDialog*>(w); d && d->isVisible()) return d;
      return static_cast<SweepDialog*>(nullptr);
    };
    QTimer::singleShot(0, this, [&] {
      SweepDialog* dialog = sweepDialog();
      if (!dialog) return;
      dialog->fromEdit()->setText(QStringLiteral("5"));
      dialog->toEdit()->setText(QStringLiteral("100"));
      dialog->countBox()->setValue(3);
      dialog->addButton()->click();
      stayed_open = dialog->isVisible();
      shown = dialog->problemLabel()->isVisible() ? dialog->problemLabel()->text() : QString();
      dialog->fromEdit()->setText(QStringLiteral("20"));
      dialog->addButton()->click();
    });
    QTimer::singleShot(20000, this, [&] {  // never hang on a dialog left open
      if (SweepDialog* dialog = sweepDialog()) dialog->reject();
    });
    QVERIFY(panel()->sweep(QStringLiteral("geometry.length")));
    QVERIFY(stayed_open);
    QVERIFY2(shown.contains(QStringLiteral("geometry.radius")), qPrintable(shown));
    QVERIFY2(shown.contains(QStringLiteral("case 0001")), qPrintable(shown));
    QCOMPARE(panel()->parameters().size(), std::size_t(1));
    QCOMPARE(panel()->parameters()[0].from, 20.0);
    QVERIFY(!panel()->isRunning());  // Add to study: nothing runs
  }

  // A cell of a table as a varied parameter, through "Add parameter…": its dialog picks the table, a row the
  // base has and a number column; the dock shows the cell by its column, table and row with its unit (the path
  // in the tooltip); its range is edited in the grid; the study saves and reopens with the cell still a
  // parameter; and every case changes that cell alone, the base's other cells kept (the rod's sections: two
  // rows, 50 m / 0.5 m and 50 m / 0.4 m).
  void aTableCellIsAddedEditedSavedAndReopened() {
    const ScenarioDocument* document = window_->document();
    const Json base_sections = document->value("sections");
    QCOMPARE(base_sections.size(), std::size_t(2));
    {
      AddParameterDialog dialog(*document->scene(), document->scenario().parameters, {});
      QVERIFY(dialog.cellButton()->isEnabled());
      QVERIFY(!dialog.chooseCell("sections", 2, "outer_diameter"));  // the base has rows 0 and 1
      QVERIFY(!dialog.chooseCell("geometry", 0, "length"));           // not a table
      QVERIFY(dialog.chooseCell("sections", 1, "outer_diameter"));
      QCOMPARE(dialog.path(), std::string("sections[1].outer_diameter"));
      QVERIFY(dialog.addButton()->isEnabled());
      QVERIFY2(dialog.summaryLabel()->text().endsWith(QStringLiteral("now 0.4")), qPrintable(dialog.summaryLabel()->text()));
      QVERIFY2(dialog.summaryLabel()->text().contains(QStringLiteral("[m]")), qPrintable(dialog.summaryLabel()->text()));
      QVERIFY(dialog.chooseField("geometry.radius"));
      QCOMPARE(dialog.path(), std::string("geometry.radius"));
      AddParameterDialog again(*document->scene(), document->scenario().parameters, {"sections[1].outer_diameter"});
      QVERIFY(again.chooseCell("sections", 0, "outer_diameter"));
      again.rowBox()->setValue(1);
      QCOMPARE(again.path(), std::string());  // varied already
      QVERIFY(!again.addButton()->isEnabled());
    }

    // The dock's button opens the real dialog (answered as a user would); the range comes from the sweep prompt.
    panel()->setSweepPrompt(answer({"", 0.2, 0.8, 4, false}, true));
    QPushButton* add = nullptr;
    for (QPushButton* b : panel()->findChildren<QPushButton*>())
      if (b->text() == QStringLiteral("Add parameter…")) add = b;
    QVERIFY(add);
    bool chose = false;
    QTimer::singleShot(0, this, [&] {
      for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* d = qobject_cast<AddParameterDialog*>(w); d && d->isVisible()) {
          chose = d->chooseCell("sections", 1, "outer_diameter");
          d->addButton()->click();
        }
    });
    QTimer::singleShot(20000, this, [&] {  // never hang on a dialog left open
      for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* d = qobject_cast<AddParameterDialog*>(w); d && d->isVisible()) d->reject();
    });
    add->click();
    QVERIFY(chose);
    QCOMPARE(panel()->parameters().size(), std::size_t(1));
    QTableWidget* table = panel()->parameterTable();
    const QString label = QStringLiteral("Outer diameter D of section row 2 [m]");
    QCOMPARE(table->item(0, 0)->text(), label);
    QCOMPARE(table->item(0, 0)->toolTip(), QStringLiteral("sections[1].outer_diameter"));  // no problem
    table->item(0, 2)->setText(QStringLiteral("0.6"));  // To
    table->item(0, 3)->setText(QStringLiteral("3"));    // Values
    QCOMPARE(panel()->parameters()[0].to, 0.6);
    QCOMPARE(panel()->parameters()[0].count, 3);

    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("cell.study.json"));
    QVERIFY2(panel()->saveStudy(file), qPrintable(panel()->lastError()));
    window_->document()->edit("geometry.length", Json(300.0));
    panel()->clearParameters();
    QVERIFY2(panel()->openStudy(file), qPrintable(panel()->lastError()));
    QCOMPARE(panel()->parameters().size(), std::size_t(1));
    QCOMPARE(panel()->parameters()[0].path, std::string("sections[1].outer_diameter"));
    QCOMPARE(panel()->parameters()[0].from, 0.2);
    QCOMPARE(panel()->parameters()[0].to, 0.6);
    QCOMPARE(panel()->parameters()[0].count, 3);
    QCOMPARE(table->item(0, 0)->text(), label);
    QCOMPARE(table->item(0, 0)->toolTip(), QStringLiteral("sections[1].outer_diameter"));
    table->item(0, 3)->setText(QStringLiteral("5"));  // the reopened grid is edited too: 0.2, 0.3, … 0.6 m

    QVERIFY2(panel()->startStudy(), qPrintable(panel()->lastError()));
    QVERIFY(runAndWait());
    QCOMPARE(panel()->session().caseCount(), 5);
    for (int c = 0; c < 5; ++c) {
      const Json& sections = panel()->session().caseScenario(c).parameters["sections"];
      QCOMPARE(sections.size(), std::size_t(2));
      QCOMPARE(sections[0], base_sections[0]);
      QCOMPARE(sections[1]["length"], base_sections[1]["length"]);
      const double expected = 0.2 + 0.1 * c;  // linear from 0.2 to 0.6 m in 4 steps
      QVERIFY2(std::abs(sections[1]["outer_diameter"].get<double>() - expected) <= 1e-12, qPrintable(QString::number(c)));
      QVERIFY(panel()->session().outcome(c).status == StudySession::Status::Finished);
    }
    StudyPlotView* view = panel()->plotView();
    const int r = view->resultBox()->findData(QStringLiteral("rod_volume"));
    QVERIFY(r >= 0);
    view->resultBox()->setCurrentIndex(r);
    QCOMPARE(view->plot()->xAxis->label(), label);  // the plot names the cell the same way
  }

  // "Sweep this cell…" in a number cell's context menu of the editor's table sweeps that cell (its study path)
  // and runs it; a row the table lacks has no menu.
  void sweepThisCellInTheEditorsTableRunsAStudyOfTheCell() {
    auto* sections = window_->editor()->findChild<TableEditor*>(QStringLiteral("field:sections"));
    QVERIFY(sections);
    QVERIFY(!sections->cellMenu(5, 1));  // no such row
    std::unique_ptr<QMenu> menu(sections->cellMenu(0, 1));
    QVERIFY(menu);
    QAction* sweep = nullptr;
    for (QAction* a : menu->actions())
      if (a->objectName() == QLatin1String("sweepCellAction")) sweep = a;
    QVERIFY(sweep);
    panel()->setSweepPrompt(answer({"", 0.3, 0.6, 4, false}));
    QSignalSpy finished(panel(), &StudyPanel::studyFinished);
    sweep->trigger();
    QCOMPARE(panel()->parameters().size(), std::size_t(1));
    QCOMPARE(panel()->parameters()[0].path, std::string("sections[0].outer_diameter"));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.first().at(0).toInt(), 4);
    for (int c = 0; c < 4; ++c) {
      const double expected = 0.3 + 0.1 * c;
      const double value = panel()->session().caseScenario(c).parameters["sections"][0]["outer_diameter"].get<double>();
      QVERIFY2(std::abs(value - expected) <= 1e-12, qPrintable(QString::number(value)));
    }
  }

  void aWindowTooNarrowForTheStudyDockBesideTheViewsGetsItFloatingAndKeepsItsWidth() {
    auto* dock = window_->findChild<QDockWidget*>(QStringLiteral("studyDock"));
    QVERIFY(dock);
    for (const int width : {1000, 2600}) {
      dock->hide();
      dock->setFloating(false);
      window_->resize(width, 740);
      QTest::qWait(50);
      const int before = window_->width();
      panel()->setSweepPrompt(answer({"", 50.0, 150.0, 5, false}, true));
      QVERIFY(chooseSweep(window_->editor(), "geometry.length"));
      QTest::qWait(100);
      QVERIFY(dock->isVisible());
      QCOMPARE(window_->width(), before);  // the window never grows past the screen for the dock
      QVERIFY2(dock->width() >= dock->minimumSizeHint().width(), qPrintable(QString::number(dock->width())));
      // 1000 px hold the views and the left column but not the dock beside them; 2600 px do.
      QCOMPARE(dock->isFloating(), width == 1000);
    }
  }

  // A scatter-diagram-like table: its column "probability" varies no parameter, so opening the table asks
  // whether it is the cases' weight (the prompt answered without a dialog); the dock shows the weighted sum
  // Σ p_i · V_i with V_i = pi r_i^2 L_i (the test scene's closed form): "—" and every case named before the
  // run, the value after it (hand-computed sum, 1e-12 relative). A failed case empties it again and is named.
  // The weighted result can be changed after the run (the outcomes stay: no rerun), the sum saves and
  // reopens with the study, and clearing it hides the sums.
  void aTableStudyShowsItsWeightedSum() {
    QTemporaryDir dir;
    const QString table = dir.filePath(QStringLiteral("sea_states.csv"));
    QFile file(table);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("geometry.length,geometry.radius,probability,run.fail\nm,m,-,-\n"
               "120,0.3,0.5,false\n80,0.2,0.3,false\n150,0.5,0.2,false\n");
    file.close();
    const double rows[3][3] = {{120, 0.3, 0.5}, {80, 0.2, 0.3}, {150, 0.5, 0.2}};
    double expected = 0.0, weight_total = 0.0;
    for (const auto& r : rows) {
      expected += r[2] * (kPi * r[1] * r[1] * r[0]);
      weight_total += r[2];
    }
    std::vector<std::string> offered;
    panel()->setWeightedSumPrompt([&offered](const std::vector<std::string>& columns, const auto&, const WeightedSumChoice&) {
      offered = columns;
      return std::optional<WeightedSumChoice>(WeightedSumChoice{"probability", {"rod_volume"}});
    });
    QVERIFY2(panel()->openCaseTable(table), qPrintable(panel()->lastError()));
    QCOMPARE(offered, std::vector<std::string>({"probability"}));  // the parameters are no candidates
    // Nor is a misspelt parameter (the engine refuses it with a guess): only the weight is offered.
    const QString misspelt = dir.filePath(QStringLiteral("misspelt.csv"));
    QFile misspelt_file(misspelt);
    QVERIFY(misspelt_file.open(QIODevice::WriteOnly));
    misspelt_file.write("geometry.lenght,probability\n120,1\n");
    misspelt_file.close();
    QCOMPARE(StudySession::nonParameterColumns(*window_->document()->scene(), window_->document()->scenario().parameters,
                                               misspelt),
             std::vector<std::string>({"probability"}));
    QCOMPARE(panel()->session().weightColumn(), std::string("probability"));
    QTableWidget* sums = panel()->weightedSumTable();
    QVERIFY(!panel()->findChild<QWidget*>(QStringLiteral("studyWeightedSums"))->isHidden());
    QVERIFY2(panel()->weightedSumHeading()->text().contains(QStringLiteral("probability")),
             qPrintable(panel()->weightedSumHeading()->text()));
    QCOMPARE(sums->rowCount(), 1);
    // Before a run the result's unit is not known yet (the runs report it); its label is read from its name.
    QCOMPARE(sums->item(0, 0)->text(), QStringLiteral("Rod volume"));
    QCOMPARE(sums->item(0, 1)->text(), QStringLiteral("—"));
    QVERIFY2(sums->item(0, 2)->text().contains(QStringLiteral("run the study")), qPrintable(sums->item(0, 2)->text()));

    QSignalSpy logged(panel(), &StudyPanel::logged);
    QVERIFY(panel()->startStudy());
    QVERIFY(runAndWait());
    bool any_sum_logged = false;
    for (const auto& entry : logged)
      any_sum_logged = any_sum_logged || entry.at(1).toString().startsWith(QStringLiteral("Weighted sum of rod_volume over probability: "));
    QVERIFY(any_sum_logged);
    bool ok = false;
    const double shown = sums->item(0, 1)->text().toDouble(&ok);
    QVERIFY2(ok, qPrintable(sums->item(0, 1)->text()));
    QVERIFY2(std::abs(shown - expected) <= 1e-12 * expected, qPrintable(QString::number(shown - expected)));
    QCOMPARE(sums->item(0, 2)->text(), QString());
    QCOMPARE(sums->item(0, 0)->text(), QStringLiteral("Rod volume [m³]"));
    test::keepScreenshot(panel()->grab().toImage(), QStringLiteral("study_weighted_sum"));
    QVERIFY2(panel()->weightedSumHeading()->text().contains(QStringLiteral("add up to 1")),
             qPrintable(panel()->weightedSumHeading()->text()));
    QCOMPARE(weight_total, 1.0);

    // Another result, chosen after the run through "Weighted sum…": shown at once from the same cases.
    QSignalSpy started(panel()->runner(), &StudyRunner::started);
    panel()->setWeightedSumPrompt([](const auto& columns, const auto& known, const WeightedSumChoice& current) {
      const bool has_volume = std::any_of(known.begin(), known.end(), [](const auto& k) { return k.first == "rod_volume"; });
      if (columns != std::vector<std::string>({"probability"}) || !has_volume || current.column != "probability")
        return std::optional<WeightedSumChoice>();
      return std::optional<WeightedSumChoice>(WeightedSumChoice{"probability", {"max_deflection", "rod_volume"}});
    });
    QVERIFY(panel()->weightedSumDialog());
    QCOMPARE(started.count(), 0);
    QCOMPARE(sums->rowCount(), 2);
    QCOMPARE(sums->item(0, 0)->text(), QStringLiteral("Max deflection [m]"));
    double deflection_sum = 0.0;
    for (int i = 0; i < 3; ++i)
      deflection_sum += rows[i][2] * panel()->session().outcome(i).results->findScalar("max_deflection")->value;
    QVERIFY(std::abs(sums->item(0, 1)->text().toDouble() - deflection_sum) <= 1e-12 * std::abs(deflection_sum));
    QVERIFY(std::abs(sums->item(1, 1)->text().toDouble() - expected) <= 1e-12 * expected);

    // Saved and reopened, the study keeps its weighted sum; run again, the same value.
    const QString study_file = dir.filePath(QStringLiteral("scatter.study.json"));
    QVERIFY2(panel()->saveStudy(study_file), qPrintable(panel()->lastError()));
    panel()->clearParameters();
    QVERIFY(panel()->findChild<QWidget*>(QStringLiteral("studyWeightedSums"))->isHidden());
    QVERIFY2(panel()->openStudy(study_file), qPrintable(panel()->lastError()));
    QCOMPARE(panel()->session().weightedResults(), std::vector<std::string>({"max_deflection", "rod_volume"}));
    QVERIFY(panel()->startStudy());
    QVERIFY(runAndWait());
    QVERIFY(std::abs(sums->item(1, 1)->text().toDouble() - expected) <= 1e-12 * expected);

    // The second case fails: no sum, and the case is named.
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("geometry.length,geometry.radius,probability,run.fail\nm,m,-,-\n"
               "120,0.3,0.5,false\n80,0.2,0.3,true\n150,0.5,0.2,false\n");
    file.close();
    panel()->setWeightedSumPrompt([](const auto&, const auto&, const WeightedSumChoice&) {
      return std::optional<WeightedSumChoice>(WeightedSumChoice{"probability", {"rod_volume"}});
    });
    QVERIFY2(panel()->openCaseTable(table), qPrintable(panel()->lastError()));
    QVERIFY(panel()->startStudy());
    QVERIFY(runAndWait());
    QCOMPARE(sums->item(0, 1)->text(), QStringLiteral("—"));
    QCOMPARE(sums->item(0, 2)->text(), QStringLiteral("failed: 0002"));

    // Not cleared while the table has its weight column (a column of no parameter is read only as weights);
    // a weight column that is not in the table is refused by name.
    QVERIFY(!panel()->setWeightedSum("", {}));
    QVERIFY2(panel()->lastError().contains(QStringLiteral("column probability varies no parameter")),
             qPrintable(panel()->lastError()));
    QVERIFY(!panel()->setWeightedSum("probabilty", {"rod_volume"}));
    QVERIFY2(panel()->lastError().contains(QStringLiteral("did you mean 'probability'")), qPrintable(panel()->lastError()));
    QCOMPARE(panel()->session().weightColumn(), std::string("probability"));  // unchanged

    // The column removed from the table: cleared, nothing shown.
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("geometry.length,geometry.radius\n120,0.3\n80,0.2\n");
    file.close();
    QVERIFY2(panel()->setWeightedSum("", {}), qPrintable(panel()->lastError()));
    QVERIFY(panel()->findChild<QWidget*>(QStringLiteral("studyWeightedSums"))->isHidden());
    QCOMPARE(panel()->session().caseCount(), 0);  // the table changed: its cases are read again at the next run
  }

  // A study folder as `maris-cli study run` leaves it (prepared by the engine's own folder code, each case's
  // summary.json written as a run writes its scalars): opened in the dock, nothing runs; the plot has the complete
  // cases' values, a failed case is named in the weighted sum's empty state; once that case is complete too, the
  // shown sum equals the hand-computed Σ p_i · V_i (1e-12 relative). A folder's study.json opens the folder.
  void aFinishedStudyFolderOpensWithItsWeightedSum() {
    QTemporaryDir dir;
    const std::filesystem::path root = dir.path().toStdString();
    {
      std::ofstream(root / "seas.csv") << "geometry.length,probability\nm,-\n120,0.6\n80,0.3\n150,0.1\n";
    }
    const auto library = test::rodLibrary();
    study::SceneSource source;
    source.scene = [&library](const std::string& name) { return library->findScene(name); };
    source.builtin = [](const std::string&) -> const Scenario* { return nullptr; };
    source.builtin_ids = [] { return std::vector<std::string>(); };
    const Json document = {{"format", study::kStudyFormat}, {"name", "seas"},
                           {"base", scenarioToJson(window_->document()->scenario())}, {"table", "seas.csv"},
                           {"results", {"rod_volume"}},
                           {"weighted_sum", {{"weight", "probability"}, {"results", {"rod_volume"}}}}};
    const study::Study definition = study::studyFromJson(document, root, source);
    const auto cases = study::expandStudy(definition);
    const study::StudyFolder folder{root / "out"};
    study::prepareStudyFolder(folder, definition, cases, root / "seas.study.json", false);
    const double radius = window_->document()->scenario().parameters["geometry"]["radius"].get<double>();
    const double lengths[3] = {120, 80, 150}, weights[3] = {0.6, 0.3, 0.1};
    auto complete = [&](int i) {
      const double volume = kPi * radius * radius * lengths[i];
      const Json summary = {{"results", {{"max_deflection", {{"value", 1.0}, {"unit", "m"}}},
                                         {"rod_volume", {{"value", volume}, {"unit", "m^3"}, {"label", "Rod volume"}}}}}};
      std::filesystem::create_directories(folder.caseRun(cases[i].id));
      std::ofstream(folder.caseRun(cases[i].id) / "summary.json") << summary.dump();
      return volume;
    };
    double expected = weights[0] * complete(0) + weights[2] * complete(2);
    study::CaseOutcome failed;
    failed.id = "0002";
    failed.status = study::CaseStatus::Failed;
    failed.exit_code = 4;
    failed.message = "node 3 displacement became non-finite";
    study::writeCaseOutcome(folder, failed);

    QVERIFY2(panel()->openStudyFolder(QString::fromStdString(folder.root.string())), qPrintable(panel()->lastError()));
    QCOMPARE(panel()->session().caseCount(), 3);
    QCOMPARE(panel()->session().outcome(1).status, StudySession::Status::Failed);
    // The study's listed result first (the plot opens on it), then the others.
    QCOMPARE(panel()->session().resultNames(), std::vector<std::string>({"rod_volume", "max_deflection"}));
    const StudyPlotData data = panel()->session().plotData("rod_volume");
    QCOMPARE(data.result[0], kPi * radius * radius * 120.0);
    QVERIFY(std::isnan(data.result[1]));
    QTableWidget* sums = panel()->weightedSumTable();
    QCOMPARE(sums->item(0, 0)->text(), QStringLiteral("Rod volume [m³]"));
    QCOMPARE(sums->item(0, 1)->text(), QStringLiteral("—"));
    QCOMPARE(sums->item(0, 2)->text(), QStringLiteral("failed: 0002"));
    // A clicked case opens its scalars in the results view (its tables stay in its run folder).
    QVERIFY(window_->openStudyCase(2));
    QTableWidget* scalars = window_->summary()->table();
    bool volume_shown = false;
    for (int row = 0; row < scalars->rowCount(); ++row)
      volume_shown = volume_shown || (scalars->item(row, 0) && scalars->item(row, 0)->text() == QStringLiteral("Rod volume"));
    QVERIFY(volume_shown);
    QVERIFY(!window_->openStudyCase(1));  // the failed case has no results to open
    QVERIFY(!panel()->startStudy());  // the CLI runs a folder's cases
    QVERIFY2(panel()->lastError().contains(QStringLiteral("--resume")), qPrintable(panel()->lastError()));

    // Case 0002 completed (`study run --resume`): its folder's study.json reopens the folder, with the whole sum.
    expected += weights[1] * complete(1);
    QVERIFY2(panel()->openStudy(QString::fromStdString(folder.manifest().string())), qPrintable(panel()->lastError()));
    QCOMPARE(panel()->session().folder(), QString::fromStdString(folder.root.string()));
    bool ok = false;
    const double shown = sums->item(0, 1)->text().toDouble(&ok);
    QVERIFY2(ok, qPrintable(sums->item(0, 1)->text()));
    QVERIFY2(std::abs(shown - expected) <= 1e-12 * expected, qPrintable(QString::number(shown - expected)));
    QCOMPARE(sums->item(0, 2)->text(), QString());
    // A sweep run from the editor while the folder is shown is a study of the open scenario (the folder holds no base).
    panel()->setSweepPrompt(answer({"", 0.2, 0.8, 3, false}));
    QVERIFY(panel()->sweep(QStringLiteral("geometry.radius")));
    QVERIFY(runAndWait());
    QCOMPARE(panel()->session().folder(), QString());
    QCOMPARE(panel()->session().caseCount(), 3);
    QCOMPARE(panel()->session().caseScenario(2).parameters["geometry"]["length"],
             window_->document()->scenario().parameters["geometry"]["length"]);
    // Not a study folder: refused by name.
    QVERIFY(!panel()->openStudyFolder(dir.path()));
    QVERIFY2(panel()->lastError().contains(QStringLiteral("study.json")), qPrintable(panel()->lastError()));
  }

  // The Study dock names the varied parameters by the scene's labels and units: the parameter table, the "against"
  // chooser, the plot's axes and legend (lines and heat map) and an opened case's run label; no dotted path in any
  // of them (a letter, a dot, a letter).
  void theStudyDockNamesParametersByTheirLabels() {
    panel()->setSweepPrompt(answer({"", 2.0, 3.0, 2, false}, true));
    QVERIFY(chooseSweep(window_->editor(), "geometry.radius"));
    panel()->setSweepPrompt(answer({"", 10.0, 1000.0, 3, true}, true));
    QVERIFY(chooseSweep(window_->editor(), "geometry.length"));
    QTableWidget* table = panel()->parameterTable();
    QCOMPARE(table->item(0, 0)->text(), QStringLiteral("Radius r [m]"));
    QCOMPARE(table->item(1, 0)->text(), QStringLiteral("Length L [m]"));
    QCOMPARE(table->item(1, 0)->toolTip(), QStringLiteral("geometry.length"));  // the path for whoever needs it
    QVERIFY(panel()->startStudy());
    QVERIFY(runAndWait());
    StudyPlotView* view = panel()->plotView();
    view->resultBox()->setCurrentIndex(view->resultBox()->findData(QStringLiteral("rod_volume")));
    view->againstBox()->setCurrentIndex(view->againstBox()->findData(QStringLiteral("geometry.length")));
    QCOMPARE(view->againstBox()->currentText(), QStringLiteral("Length L [m]"));
    const QRegularExpression dotted(QStringLiteral("[A-Za-z_]\\.[A-Za-z_]"));
    const auto noPath = [&](const PlotWords& texts) {
      for (const QString& text : QStringList{texts.title} + texts.axes + texts.legend)
        if (text.contains(dotted)) return false;
      return true;
    };
    PlotWords texts = plotWords(*view->plot());
    QCOMPARE(texts.axes.size(), 2);
    QCOMPARE(texts.axes[0], QStringLiteral("Length L [m]"));
    QCOMPARE(texts.legend, QStringList({QStringLiteral("Radius r [m] = 2"), QStringLiteral("Radius r [m] = 3")}));
    QVERIFY2(noPath(texts), qPrintable(texts.title + " | " + texts.axes.join(" | ") + " | " + texts.legend.join(" | ")));
    view->kindBox()->setCurrentIndex(1);  // heat map over length and radius
    QCOMPARE(view->drawn().kind, StudyPlotKind::HeatMap);
    texts = plotWords(*view->plot());
    QCOMPARE(texts.axes.mid(0, 2), QStringList({QStringLiteral("Length L [m]"), QStringLiteral("Radius r [m]")}));
    QVERIFY2(noPath(texts), qPrintable(texts.axes.join(" | ")));
    test::keepScreenshot(window_->grab().toImage(), QStringLiteral("study_labels"));
    // Cases in the grid's order (alphabetical paths, the last fastest): case 0001 is L = 10 m, r = 2 m.
    QVERIFY(window_->openStudyCase(0));
    QCOMPARE(window_->history().runs().back().label,
             QStringLiteral("study case 0001 (Length L [m] = 10, Radius r [m] = 2)"));
  }

  // A study folder that the command line ran (each case run by the engine and written by the run folder's writer,
  // as `maris-cli run --out` writes it): a clicked case opens its full results from its case folder, its plots and
  // tables equal to the case's CSV files (exactly: 17 significant digits), and the log says that a case folder holds
  // no 3D view; a failed case says it failed and why.
  void aCaseOfAnOpenedStudyFolderOpensItsFullResults() {
    QTemporaryDir dir;
    const std::filesystem::path root = dir.path().toStdString();
    const auto library = test::rodLibrary();
    study::SceneSource source;
    source.scene = [&library](const std::string& name) { return library->findScene(name); };
    source.builtin = [](const std::string&) -> const Scenario* { return nullptr; };
    source.builtin_ids = [] { return std::vector<std::string>(); };
    const Json document = {{"format", study::kStudyFormat}, {"name", "lengths"},
                           {"base", scenarioToJson(window_->document()->scenario())},
                           {"grid", {{"geometry.length", {60, 90, 120}}}}};
    const study::Study definition = study::studyFromJson(document, root, source);
    const auto cases = study::expandStudy(definition);
    const study::StudyFolder folder{root / "out"};
    study::prepareStudyFolder(folder, definition, cases, root / "lengths.study.json", false);
    for (int i : {0, 1}) {
      RunContext context({}, nullptr);
      const Results results = runScenario(*library->findScene(cases[i].scenario.scene), cases[i].scenario, context);
      writeRunFolder(folder.caseRun(cases[i].id), cases[i].scenario, results, std::chrono::system_clock::now());
    }
    study::CaseOutcome failed;
    failed.id = "0003";
    failed.status = study::CaseStatus::Failed;
    failed.exit_code = 3;
    failed.message = "node 3 displacement became non-finite";
    study::writeCaseOutcome(folder, failed);
    QVERIFY2(panel()->openStudyFolder(QString::fromStdString(folder.root.string())), qPrintable(panel()->lastError()));

    QVERIFY(window_->openStudyCase(1));  // L = 90 m
    const RunRecord& shown = window_->history().runs().back();
    QVERIFY2(shown.label.startsWith(QStringLiteral("study case 0002 (Length L [m] = 90)")), qPrintable(shown.label));
    QVERIFY(!shown.results->plots.empty());
    QCOMPARE(window_->plots()->count(), static_cast<int>(shown.results->plots.size()));
    const PlotSpec& spec = shown.results->plots.front();
    // The case's CSV of the first plot's table, read here on its own: names, units, then the data.
    std::ifstream csv(folder.caseRun("0002") / (spec.table + ".csv"));
    std::string names, units, first;
    std::getline(csv, names);
    std::getline(csv, units);
    std::getline(csv, first);
    const QStringList header = QString::fromStdString(names).split(QLatin1Char(','));
    const QStringList values = QString::fromStdString(first).split(QLatin1Char(','));
    const Table* table = shown.results->findTable(spec.table);
    QVERIFY(table);
    QCOMPARE(static_cast<int>(table->columns.size()), header.size());
    const int y = static_cast<int>(header.indexOf(QString::fromStdString(spec.y.front())));
    QVERIFY(y >= 0);
    PlotView* plot = nullptr;
    for (int v = 0; v < window_->plots()->count(); ++v)
      if (window_->plots()->view(v)->spec().name == spec.name) plot = window_->plots()->view(v);
    QVERIFY(plot);
    QVERIFY(plot->plot()->graphCount() > 0);
    QCOMPARE(plot->plot()->graph(0)->data()->at(0)->value, values[y].toDouble());
    QCOMPARE(table->columns[y].values.front(), values[y].toDouble());
    QCOMPARE(window_->sceneView()->frameCount(), 0);  // no 3D view in a case folder, and the log says so
    QVERIFY2(window_->runPanel()->logView()->toPlainText().contains(QStringLiteral("3D view")),
             qPrintable(window_->runPanel()->logView()->toPlainText()));
    test::keepScreenshot(window_->grab().toImage(), QStringLiteral("study_folder_case"));

    QVERIFY(!window_->openStudyCase(2));  // failed: nothing to show, and why
    QVERIFY2(window_->runPanel()->logView()->toPlainText().contains(
                 QStringLiteral("study case 0003 (Length L [m] = 120) failed: node 3 displacement became non-finite")),
             qPrintable(window_->runPanel()->logView()->toPlainText()));
  }

  // The dialog: no column, no sum; a column needs at least one result (checked or typed).
  void theWeightedSumDialogNeedsAResultForAColumn() {
    WeightedSumDialog dialog({"probability"}, {{"rod_volume", "rod_volume"}}, WeightedSumChoice{});
    QVERIFY(dialog.okButton()->isEnabled());
    QCOMPARE(dialog.choice(), WeightedSumChoice{});
    dialog.columnBox()->setCurrentIndex(dialog.columnBox()->findText(QStringLiteral("probability")));
    QVERIFY(!dialog.okButton()->isEnabled());
    dialog.resultList()->item(0)->setCheckState(Qt::Checked);
    QVERIFY(dialog.okButton()->isEnabled());
    dialog.otherResults()->setText(QStringLiteral(" max_deflection , rod_volume"));
    QCOMPARE(dialog.choice(), (WeightedSumChoice{"probability", {"rod_volume", "max_deflection"}}));
  }

  void aStudyWithABadCaseRunsNothing() {
    // The radius must stay below half the length: with r = 5 m the case L = 5 m is refused by the
    // scene's cross-field check (at geometry.radius), the others are valid.
    window_->document()->edit("geometry.radius", Json(5.0));
    panel()->setSweepPrompt(answer({"", 5.0, 100.0, 3, false}));
    QSignalSpy started(panel()->runner(), &StudyRunner::started);
    QVERIFY(!panel()->sweep(QStringLiteral("geometry.length")));
    QCOMPARE(started.count(), 0);
    QVERIFY(!panel()->isRunning());
    QVERIFY2(panel()->lastError().contains(QStringLiteral("geometry.radius")), qPrintable(panel()->lastError()));
    QVERIFY2(panel()->lastError().contains(QStringLiteral("nothing was run")), qPrintable(panel()->lastError()));
  }
};

QTEST_MAIN(StudyTest)
#include "test_study.moc"
