// Reference data a user imports onto a plot (a paper's points as CSV) and the CSV export of every
// kept run of a plot, on Qt's offscreen platform.
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

#include <fstream>

#include "plots/plot_export.hpp"
#include "plots/plot_panel.hpp"
#include "plots/reference_data.hpp"
#include "plots/result_plot.hpp"
#include "run/run_controller.hpp"
#include "test_scene.hpp"
#include "ui_test_support.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

void writeText(const QString& file, const std::string& text) {
  std::ofstream out(file.toStdString(), std::ios::binary);
  out << text;
}

}  // namespace

class ReferenceTest : public QObject {
  Q_OBJECT

  SceneDefinition scene_ = test::makeRodScene();

  RunRecord finishedRun(int point_count, quint64 id) {
    Scenario s = defaultScenario(scene_);
    s.parameters["discretisation"]["point_count"] = point_count;
    RunController controller;
    QSignalSpy finished(&controller, &RunController::finished);
    controller.start(scene_, s);
    if (!finished.wait(20000)) return {};
    RunRecord r = finished.takeFirst().at(0).value<RunRecord>();
    r.id = id;
    r.label = QStringLiteral("run %1").arg(id);
    return r;
  }

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void csvWrittenByMarisReadsBackExactly() {
    Table t;
    t.name = "history";
    t.add("time", "s", {0.0, 0.1, 1.0 / 3.0});
    t.add("tip_x", "m", {1e-17, -2.5e6, 0.1 + 0.2});
    const Table back = tableFromCsv(t.toCsv(), "history");
    QCOMPARE(back.columns.size(), std::size_t(2));
    QCOMPARE(back.columns[1].name, std::string("tip_x"));
    QCOMPARE(back.columns[1].unit, std::string("m"));
    // toCsv writes 17 significant digits: the doubles come back bit for bit.
    for (std::size_t c = 0; c < 2; ++c) QVERIFY(back.columns[c].values == t.columns[c].values);
  }

  void digitisedCsvWithUnitsInTheNamesRow() {
    const Table t = tableFromCsv("# Fig. 7 of the paper, digitised\r\n"
                                 "\xEF\xBB\xBF" "arc length [m]; deflection (mm)\r\n"
                                 "0; 0\r\n\r\n"
                                 "50;  1.5e1\r\n"
                                 "100; +42\r\n",
                                 "fig7");
    QCOMPARE(t.columns[0].name, std::string("arc length"));
    QCOMPARE(t.columns[0].unit, std::string("m"));
    QCOMPARE(t.columns[1].name, std::string("deflection"));
    QCOMPARE(t.columns[1].unit, std::string("mm"));
    QVERIFY((t.columns[1].values == std::vector<double>{0.0, 15.0, 42.0}));
  }

  void badCsvIsExplainedByLineAndColumn() {
    auto message = [](const std::string& text) -> std::string {
      try {
        tableFromCsv(text, "data");
      } catch (const std::runtime_error& e) {
        return e.what();
      }
      return "(accepted)";
    };
    const std::string not_number = message("x,y\nm,m\n1,2\n3,abc\n");
    QVERIFY2(not_number.find("line 4, column 2 (y): expected a number, found \"abc\"") != std::string::npos, not_number.c_str());
    const std::string short_row = message("x,y\n1,2\n3\n");
    QVERIFY2(short_row.find("line 3: expected 2 cells (as the first row), found 1") != std::string::npos, short_row.c_str());
    QVERIFY(message("x,y\nm,m\n").find("no rows of numbers") != std::string::npos);
    QVERIFY(message("one_column\n1\n").find("at least 2 are needed") != std::string::npos);
    QVERIFY(message("").find("no table") != std::string::npos);
  }

  void columnsAreMatchedByNameElseByPosition() {
    PlotSpec spec;
    spec.x = "time";
    spec.y = {"tip_x", "mid_x"};
    Table named;
    named.add("mid_x", "m", {1});
    named.add("time", "s", {0});
    named.add("other", "m", {2});
    ReferenceColumns m = matchReferenceColumns(named, spec);
    QCOMPARE(m.x->name, std::string("time"));
    QCOMPARE(m.y.size(), std::size_t(1));
    QCOMPARE(m.y[0]->name, std::string("mid_x"));
    Table anonymous;
    anonymous.add("t", "s", {0});
    anonymous.add("a", "m", {1});
    anonymous.add("b", "m", {2});
    m = matchReferenceColumns(anonymous, spec);
    QCOMPARE(m.x->name, std::string("t"));
    QCOMPARE(m.y.size(), std::size_t(2));
  }

  void importedPointsAppearOnThePlotAndStayForLaterRuns() {
    const RunRecord first = finishedRun(50, 1);
    QVERIFY(first.results);
    PlotPanel panel;
    panel.resize(800, 600);
    panel.showResults(first.results, first.label);
    QSignalSpy messages(&panel, &PlotPanel::message);
    QTemporaryDir dir;
    const QString paper = dir.filePath(QStringLiteral("paper_points.csv"));
    writeText(paper, "arc_length,deflection\nm,mm\n0,0\n40,0.001\n80,0.002\n100,0.003\n");
    QCOMPARE(panel.tabs()->currentIndex(), 0);
    const int before = panel.view(0)->plot()->graphCount();  // the curve and the scene's own reference points
    QVERIFY(panel.addReferenceFile(paper));
    QCustomPlot* plot = panel.view(0)->plot();
    QCOMPARE(plot->graphCount(), before + 1);
    QCPGraph* markers = plot->graph(before);
    QCOMPARE(markers->dataCount(), 4);
    QCOMPARE(markers->data()->at(1)->key, 40.0);
    QCOMPARE(markers->data()->at(1)->value, 0.001);
    QCOMPARE(markers->lineStyle(), QCPGraph::lsNone);
    // (its whole name: a narrow plot shortens legend entries in the middle)
    QVERIFY2(fullGraphName(*markers).startsWith(QStringLiteral("paper_points")), qPrintable(fullGraphName(*markers)));
    // The unit differs from the plot's (mm against m): said, not silently converted.
    QVERIFY2(messages.last().at(0).toString().contains(QStringLiteral("in mm, the plot's axis in m")),
             qPrintable(messages.last().at(0).toString()));
    // The x axis now spans the markers too.
    QVERIFY(plot->xAxis->range().contains(40.0));

    // A later run of the scene keeps the reference on the same tab.
    const RunRecord second = finishedRun(20, 2);
    panel.showResults(second.results, second.label);
    QCOMPARE(panel.view(0)->plot()->graphCount(), before + 1);
    // Other tabs have none.
    QCOMPARE(panel.view(1)->references().size(), std::size_t(0));

    // A bad file is refused with its reason; the plot keeps what it had.
    const QString bad = dir.filePath(QStringLiteral("bad.csv"));
    writeText(bad, "arc_length,deflection\n0,zero\n");
    QVERIFY(!panel.addReferenceFile(bad));
    QVERIFY2(messages.last().at(0).toString().contains(QStringLiteral("line 2, column 2")),
             qPrintable(messages.last().at(0).toString()));
    QCOMPARE(panel.view(0)->plot()->graphCount(), before + 1);

    panel.clearReferences();
    QCOMPARE(panel.view(0)->plot()->graphCount(), before);
  }

  void csvOfAllKeptRunsHasEveryRunsRows() {
    const RunRecord a = finishedRun(50, 1), b = finishedRun(20, 2);
    QVERIFY(a.results && b.results);
    PlotPanel panel;
    panel.resize(800, 600);
    panel.showResults(b.results, b.label);
    panel.setAvailableRuns({a, b}, b.id);
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("deflection_runs.csv"));
    panel.exportAllRunsCsv(file);
    QFile in(file);
    QVERIFY(in.open(QIODevice::ReadOnly));
    // Every row names its run's scenario in the second column; without it the rest is the numeric table.
    const QString scenario = QStringLiteral("\"%1\"").arg(QString::fromStdString(a.scenario.name));
    QStringList numeric;
    int line = 0;
    for (const QString& row : QString::fromUtf8(in.readAll()).split('\n', Qt::SkipEmptyParts)) {
      QStringList cells = row.split(',');
      QCOMPARE(cells.value(1), line == 0 ? QStringLiteral("\"scenario\"") : line == 1 ? QStringLiteral("\"-\"") : scenario);
      cells.removeAt(1);
      numeric << cells.join(',');
      ++line;
    }
    const Table back = tableFromCsv(numeric.join('\n').toStdString() + "\n", "runs");
    QCOMPARE(back.columns.size(), std::size_t(3));
    QCOMPARE(back.columns[0].name, std::string("run"));
    QCOMPARE(back.columns[1].name, std::string("arc_length"));
    QCOMPARE(back.columns[1].unit, std::string("m"));
    QCOMPARE(back.columns[2].name, std::string("deflection"));
    QCOMPARE(back.rows(), std::size_t(50 + 20));
    // Run 1 first (50 points), then run 2 (20 points), each from 0 to the rod's length.
    QCOMPARE(back.columns[0].values.front(), 1.0);
    QCOMPARE(back.columns[0].values.back(), 2.0);
    QCOMPARE(std::count(back.columns[0].values.begin(), back.columns[0].values.end(), 2.0), 20);
    QCOMPARE(back.columns[1].values[49], a.results->findTable("profile")->find("arc_length")->values.back());
    QCOMPARE(back.columns[1].values[50], 0.0);
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1);  // no temporary file left
  }
};

QTEST_MAIN(ReferenceTest)
#include "test_reference.moc"
