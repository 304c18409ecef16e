// The views of a finished run, on Qt's offscreen platform: the results table copied and exported,
// the report's summary.md with awkward names, the folder a dialog starts in, the run panel's
// log and progress after a cancel, and the plot a finished run opens on.
#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QScrollBar>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <qcustomplot.h>

#include "catalog.hpp"
#include "core/run_context.hpp"
#include "core/scenario.hpp"
#include "plots/plot_panel.hpp"
#include "plots/display_units.hpp"
#include "plots/result_plot.hpp"
#include "plots/plot_export.hpp"
#include "run/results_summary.hpp"
#include "run/run_controller.hpp"
#include "run/run_panel.hpp"
#include "start_folder.hpp"
#include "ui_test_support.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

// A finished run of the scenario "Rod" with these results.
RunRecord runOf(Results results) {
  RunRecord record;
  record.id = 1;
  record.scenario.name = "Rod";
  record.results = std::make_shared<Results>(std::move(results));
  record.label = QStringLiteral("run 1");
  return record;
}

// Two scalars whose values are exact in binary, so their printed forms are known: 0.125 and 2.5.
RunRecord twoScalarRun() {
  Results results;
  results.addScalar("tip_deflection", 0.125, "m", "Tip deflection");
  results.addScalar("period", 2.5, "s", "First period", "T₁");
  return runOf(std::move(results));
}

// Table separators of one Markdown row: '|' not escaped by a backslash.
int unescapedPipes(const std::string& line) {
  int n = 0;
  for (std::size_t i = 0; i < line.size(); ++i)
    if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) ++n;
  return n;
}

// A table "t" over x = 0, 1, 2 with one column per (name, values), each drawn in a plot of the same name.
Results plotsOf(const std::vector<std::pair<std::string, std::vector<double>>>& columns) {
  Results r;
  Table& t = r.tables.emplace_back();
  t.name = std::string(1, 't');  // (GCC 12 reports a false -Warray-bounds for a one-letter literal assigned here)
  t.add("x", "s", {0.0, 1.0, 2.0});
  for (const auto& [name, values] : columns) {
    t.add(name, "m", values);
    r.plots.push_back(makePlot(name, name, "t", "x", {name}));
  }
  return r;
}

// A built-in scenario run as the GUI runs it, shown in `panel` as the main window shows a finished run.
std::shared_ptr<const Results> showBuiltin(PlotPanel& panel, const std::string& id) {
  const BuiltinScenario* b = findBuiltin(id);
  if (!b) return nullptr;
  const SceneDefinition& scene = requireScene(b->scenario.scene);
  RunContext context({}, nullptr);
  auto results = std::make_shared<const Results>(runScenario(scene, b->scenario, context));
  panel.setDeclaredGroups(scene.plot_groups);
  panel.showResults(results, QStringLiteral("run 1"));
  panel.showPlotWithData();
  return results;
}

}  // namespace

class ResultsViewsTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { test::isolateSettings(); }

  // Zeros and round-off are no data; a small value beside nothing larger in its unit is.
  void plotCarriesDataIgnoresZerosAndRoundOff() {
    const Results r = plotsOf({{"zero", {0.0, 0.0, 0.0}},
                               {"round_off", {0.0, 2e-14, 0.0}},
                               {"depth", {-100.0, -50.0, 0.0}},
                               {"nan", {std::nan(""), 0.0, 0.0}}});
    QVERIFY(!plotCarriesData(r, r.plots[0]));
    QVERIFY(!plotCarriesData(r, r.plots[1]));  // 2e-16 of the 100 m beside it
    QVERIFY(plotCarriesData(r, r.plots[2]));
    QVERIFY(!plotCarriesData(r, r.plots[3]));
    const Results alone = plotsOf({{"tiny", {0.0, 1e-9, 0.0}}});
    QVERIFY(plotCarriesData(alone, alone.plots[0]));
  }

  // A finished run whose first plot is all zeros opens on the first plot with data, unless the user chose the plot.
  void finishedRunOpensOnAPlotWithData() {
    auto r = std::make_shared<const Results>(plotsOf({{"history", {0.0, 0.0, 0.0}}, {"shape", {1.0, 2.0, 3.0}}}));
    PlotPanel panel;
    panel.resize(600, 400);
    panel.showResults(r, QStringLiteral("run 1"));
    QCOMPARE(panel.tabs()->currentIndex(), 0);
    panel.showPlotWithData();
    QCOMPARE(panel.tabs()->currentIndex(), 1);
    // The user's own choice of the empty plot stays, for this run and the next.
    emit panel.tabs()->tabBarClicked(0);
    panel.tabs()->setCurrentIndex(0);
    QVERIFY(panel.userChosePlot());
    panel.showResults(r, QStringLiteral("run 2"));
    panel.showPlotWithData();
    QCOMPARE(panel.tabs()->currentIndex(), 0);
    // Another scenario (clear()) chooses again; a plot with data is left as it is.
    panel.clear();
    panel.showResults(r, QStringLiteral("run 3"));
    panel.showPlotWithData();
    QCOMPARE(panel.tabs()->currentIndex(), 1);
    auto both = std::make_shared<const Results>(plotsOf({{"a", {0.0, 1.0, 0.0}}, {"b", {1.0, 2.0, 3.0}}}));
    panel.clear();
    panel.showResults(both, QStringLiteral("run 4"));
    panel.showPlotWithData();
    QCOMPARE(panel.tabs()->currentIndex(), 0);
  }

  // The statics-and-modes-only riser opens on a plot with its result (its stress profile is zero, its shape
  // round-off), a dynamic riser on its first plot, the probe's displacement over time.
  void builtInRunsOpenOnTheirResult() {
    if (!findBuiltin("riser_paper_case3_pretensioned") || !findBuiltin("riser_peer_fixed_height"))
      QSKIP("the riser scene is not built in");
    PlotPanel statics;
    statics.resize(600, 400);
    const auto modes_run = showBuiltin(statics, "riser_paper_case3_pretensioned");
    const PlotSpec& shown = statics.currentView()->spec();
    QVERIFY2(plotCarriesData(*modes_run, shown), shown.name.c_str());
    QVERIFY2(shown.name.rfind("frequency_", 0) == 0, shown.name.c_str());
    PlotPanel dynamic;
    dynamic.resize(600, 400);
    const auto dynamic_run = showBuiltin(dynamic, "riser_peer_fixed_height");
    QVERIFY(!dynamic.groups().empty());
    QCOMPARE(dynamic.tabs()->currentIndex(), dynamic.groups().front().plots.front());
    QVERIFY(plotCarriesData(*dynamic_run, dynamic.currentView()->spec()));
    QCOMPARE(dynamic.currentView()->spec().table, std::string("history"));
  }

  void copyPutsTabSeparatedScalarsWithHeaderOnTheClipboard() {
    ResultsSummary summary;
    summary.showRun(twoScalarRun());
    summary.show();
    QVERIFY(QTest::qWaitForWindowExposed(&summary));
    summary.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&summary));
    summary.table()->setFocus();
    QApplication::clipboard()->clear();
    // Labels for people: the declared one ("T₁"), else the name made readable ("Tip deflection").
    QCOMPARE(summary.table()->item(0, 0)->text(), QStringLiteral("Tip deflection"));
    QCOMPARE(summary.table()->item(1, 0)->text(), QStringLiteral("T₁"));
    // Nothing selected: Ctrl+C copies every scalar, one row each after the header.
    QTest::keyClick(summary.table(), Qt::Key_C, Qt::ControlModifier);
    QCOMPARE(QApplication::clipboard()->text(),
             QStringLiteral("Quantity\tValue\tUnit\tMeaning\n"
                            "Tip deflection\t0.125\tm\tTip deflection\n"
                            "T₁\t2.5\ts\tFirst period\n"));
    // One row selected: the context menu's Copy copies that row only.
    summary.table()->selectRow(1);
    QVERIFY(summary.table()->actions().contains(summary.copyAction()));
    summary.copyAction()->trigger();
    QCOMPARE(QApplication::clipboard()->text(),
             QStringLiteral("Quantity\tValue\tUnit\tMeaning\nT₁\t2.5\ts\tFirst period\n"));
  }

  void exportWritesNamesUnitsAndValuesAsCsv() {
    ResultsSummary summary;
    QTemporaryDir dir;
    const std::filesystem::path file = dir.filePath(QStringLiteral("scalars.csv")).toStdString();
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, summary.exportCsv(file));  // no run shown yet
    QVERIFY(!summary.exportAction()->isEnabled());
    summary.showRun(twoScalarRun());
    QVERIFY(summary.exportAction()->isEnabled());
    summary.exportCsv(file);
    // The engine's CSV layout (Table::toCsv): names row, units row, then the values.
    QCOMPARE(QString::fromStdString(readTextFile(file)), QStringLiteral("tip_deflection,period\nm,s\n0.125,2.5\n"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{QStringLiteral("scalars.csv")});
  }

  void summaryMarkdownEscapesPipesBackslashesAndNewlines() {
    Results results;
    results.addScalar("force|moment", 1.5, "N\\m", "first line\nsecond | line");
    Scenario scenario;
    scenario.name = "Pipes";
    scenario.scene = "rod";
    const std::string md = summaryMarkdown(scenario, results, {});
    const std::string row = "| force\\|moment | 1.5 | N\\\\m | first line<br>second \\| line |";
    QVERIFY2(md.find(row + "\n") != std::string::npos, md.c_str());
    // The row has the header's five separators, so the table keeps its four columns.
    QCOMPARE(unescapedPipes(row), unescapedPipes("| quantity | value | unit | meaning |"));
    QCOMPARE(unescapedPipes(row), 5);
    QCOMPARE(markdownTableCell("a\r\nb"), std::string("a<br>b"));
  }

  void displayUnitsChangeWhatIsShownNotWhatIsWritten() {
    QCOMPARE(displayUnitChoices("Pa"), (std::vector<std::string>{"Pa", "kPa", "MPa", "GPa"}));
    QCOMPARE(displayUnitChoices("m"), (std::vector<std::string>{"mm", "m"}));
    QVERIFY(displayUnitChoices("s").empty());
    setDisplayUnit("Pa", "furlong");  // not a choice: SI
    QCOMPARE(displayUnit("Pa").unit, std::string("Pa"));
    setDisplayUnit("m", "mm");
    ResultsSummary summary;
    summary.showRun(twoScalarRun());
    QCOMPARE(summary.table()->item(0, 1)->text(), QStringLiteral("125"));  // 0.125 m
    QCOMPARE(summary.table()->item(0, 2)->text(), QStringLiteral("mm"));
    QCOMPARE(summary.table()->item(1, 2)->text(), QStringLiteral("s"));  // seconds take no prefix here
    QTemporaryDir dir;
    const std::filesystem::path file = dir.filePath(QStringLiteral("scalars.csv")).toStdString();
    summary.exportCsv(file);  // the file stays SI
    QCOMPARE(QString::fromStdString(readTextFile(file)), QStringLiteral("tip_deflection,period\nm,s\n0.125,2.5\n"));
    Results results;
    Table tip;
    tip.name = "tip";
    tip.add("time", "s", {0.0, 1.0}, "Time");
    tip.add("tip_x", "m", {0.5, 0.25}, "Tip x");
    results.tables.push_back(tip);
    QCustomPlot plot;
    QVERIFY(fillPlot(plot, results, makePlot("tip", "Tip", "tip", "time", {"tip_x"})));
    QCOMPARE(plot.axisRect()->axis(QCPAxis::atLeft)->label(), QStringLiteral("Tip x [mm]"));
    QCOMPARE(plot.axisRect()->axis(QCPAxis::atBottom)->label(), QStringLiteral("Time [s]"));
    QCOMPARE(plot.graph(0)->data()->at(1)->value, 250.0);
    setDisplayUnit("m", "m");
    QVERIFY(fillPlot(plot, results, makePlot("tip", "Tip", "tip", "time", {"tip_x"})));
    QCOMPARE(plot.graph(0)->data()->at(1)->value, 0.25);
  }

  // The engine declares units in ASCII ("kg/m^3"); what people read has superscripts, middle dots and degree signs,
  // on axes and in the results dock alike, while the CSV keeps the declared form.
  void unitsAreShownInTypographicForm() {
    QCOMPARE(unitText("kg/m^3"), QStringLiteral("kg/m³"));
    QCOMPARE(unitText("N^2*m^2*s/rad"), QStringLiteral("N²·m²·s/rad"));
    QCOMPARE(unitText("deg"), QStringLiteral("°"));
    QCOMPARE(unitText("degC"), QStringLiteral("°C"));
    QCOMPARE(unitText("1/s"), QStringLiteral("1/s"));
    QVERIFY(unitText("-").isEmpty());
    QVERIFY(unitText("").isEmpty());
    QCOMPARE(axisLabel("Density", "kg/m^3"), QStringLiteral("Density [kg/m³]"));
    QCOMPARE(axisLabel("Ratio", "-"), QStringLiteral("Ratio"));
    Results results;
    results.addScalar("water_density", 1025.0, "kg/m^3", "Water density", "ρ");
    ResultsSummary summary;
    summary.showRun(runOf(results));
    QCOMPARE(summary.table()->item(0, 2)->text(), QStringLiteral("kg/m³"));
    QTemporaryDir dir;
    const std::filesystem::path file = dir.filePath(QStringLiteral("scalars.csv")).toStdString();
    summary.exportCsv(file);
    QCOMPARE(QString::fromStdString(readTextFile(file)), QStringLiteral("water_density\nkg/m^3\n1025\n"));
  }

  void dialogsStartInAnExistingFolder() {
    QTemporaryDir dir;
    QCOMPARE(startFolder(dir.path()), QFileInfo(dir.path()).absoluteFilePath());
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString fallback = QFileInfo(documents).isDir() ? documents : QDir::homePath();
    const QString gone = dir.filePath(QStringLiteral("removed/folder"));
    QCOMPARE(startFolder(gone), fallback);
    QCOMPARE(startFolder({}), fallback);
    QFile file(dir.filePath(QStringLiteral("a.txt")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.close();
    QCOMPARE(startFolder(file.fileName()), fallback);  // a file is not a folder to start in
    QVERIFY(QFileInfo(fallback).isDir());
  }

  void runLogFollowsItsNewestLineUnlessScrolledUp() {
    RunController controller;
    QAction run(QStringLiteral("Run")), cancel(QStringLiteral("Cancel"));
    RunPanel panel(&controller, &run, &cancel);
    panel.resize(420, 220);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QScrollBar* bar = panel.logView()->verticalScrollBar();
    for (int i = 0; i < 60; ++i)
      panel.log(i % 7 ? RunPanel::Level::Info : RunPanel::Level::Warning,
                QStringLiteral("line %1: a message long enough to wrap in a narrow dock,\nwith a second line").arg(i));
    QVERIFY(bar->maximum() > 0);
    QCOMPARE(bar->value(), bar->maximum());
    // Scrolled up by the user: new lines do not pull the view down.
    bar->setValue(bar->maximum() / 3);
    const int kept = bar->value();
    panel.log(RunPanel::Level::Info, QStringLiteral("one more"));
    QCOMPARE(bar->value(), kept);
    // Back at the bottom: it follows again.
    bar->setValue(bar->maximum());
    panel.log(RunPanel::Level::Error, QStringLiteral("and another"));
    QCOMPARE(bar->value(), bar->maximum());
    QVERIFY(panel.logView()->toPlainText().endsWith(QStringLiteral("error: and another")));
  }

  void cancelResetsProgressAndTimeLeft() {
    RunController controller;
    QAction run(QStringLiteral("Run")), cancel(QStringLiteral("Cancel"));
    RunPanel panel(&controller, &run, &cancel);
    emit controller.progressed(0.44, QStringLiteral("stepping"), 6.8, 8.6);
    QCOMPARE(panel.progressBar()->value(), 440);
    QVERIFY2(panel.timeLabel()->text().contains(QStringLiteral("about 8.6 s left")), qPrintable(panel.timeLabel()->text()));
    emit controller.cancelled();
    QCOMPARE(panel.progressBar()->value(), 0);
    QCOMPARE(panel.timeLabel()->text(), QString());
    emit controller.progressed(0.5, QStringLiteral("stepping"), 1.0, 1.0);
    emit controller.failed(QStringLiteral("diverged"));
    QCOMPARE(panel.progressBar()->value(), 0);
    QCOMPARE(panel.timeLabel()->text(), QString());
  }
};

QTEST_MAIN(ResultsViewsTest)
#include "test_results.moc"
