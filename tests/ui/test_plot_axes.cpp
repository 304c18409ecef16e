// A plot's axes as fillPlot draws them: reference points (the scene's own and a user's) lie inside the fitted
// ranges with room for their markers, quantities whose sizes differ by more than 100× get their own y axis (a third
// one when the smaller ones differ by 100× again), legend entries too wide for a narrow plot are shortened, and a
// legend sits at a corner no curve passes through, else under the axes.
// Values are built here, so every expected range and axis follows from them.
#include <QtTest>
#include <qcustomplot.h>

#include <array>
#include <cmath>
#include <vector>

#include "plots/plot_axes.hpp"
#include "plots/result_plot.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

// A table "curve" of x = 0 … 1 [m] (21 points) and one column per (name, unit, size): size · (1 + x) / 2, labelled
// by its name.
Results curves(const std::vector<std::tuple<std::string, std::string, double>>& columns) {
  Results r;
  Table& t = r.tables.emplace_back();
  t.name = "curve";
  std::vector<double> x;
  for (int i = 0; i <= 20; ++i) x.push_back(i / 20.0);
  t.add("x", "m", x, "x");
  for (const auto& [name, unit, size] : columns) {
    std::vector<double> y;
    for (double v : x) y.push_back(size * (1.0 + v) / 2.0);
    t.add(name, unit, y, name);
  }
  return r;
}

Table points(const std::string& name, const std::string& y_name, std::vector<double> x, std::vector<double> y) {
  Table t;
  t.name = name;
  t.title = "Measured points";
  t.add("x", "m", std::move(x));
  t.add(y_name, "m", std::move(y));
  return t;
}

// Where `v` sits in `axis`'s range, 0 at the lower end and 1 at the upper (in decades on a log axis).
double place(const QCPAxis* axis, double v) {
  const QCPRange r = axis->range();
  if (axis->scaleType() == QCPAxis::stLogarithmic) return std::log(v / r.lower) / std::log(r.upper / r.lower);
  return (v - r.lower) / r.size();
}

// Every point of every marker graph lies at least `room` of the range inside both axes' ends.
void requireMarkersInside(const QCustomPlot& plot, double room, int expected_markers) {
  int markers = 0;
  for (int i = 0; i < plot.graphCount(); ++i) {
    const QCPGraph* g = plot.graph(i);
    if (g->lineStyle() != QCPGraph::lsNone) continue;
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it, ++markers) {
      for (const double p : {place(g->keyAxis(), it->key), place(g->valueAxis(), it->value)})
        QVERIFY2(p >= room && p <= 1.0 - room,
                 qPrintable(QStringLiteral("%1 at (%2, %3): %4 of the range").arg(g->name()).arg(it->key).arg(it->value).arg(p)));
    }
  }
  QCOMPARE(markers, expected_markers);
}

}  // namespace

class TestPlotAxes : public QObject {
  Q_OBJECT

 private slots:
  // Measured points below the curve's minimum and beyond its x range (as the towing-tank points of a
  // resistance curve): the fitted ranges hold them with at least 3 % of the range to spare (the margin is 4 % of
  // the range before widening, 4/108 = 3.7 % after).
  void referencePointsAreInsideTheAxes() {
    Results r = curves({{"y", "m", 2.0}});  // y from 1 to 2
    r.tables.push_back(points("measured", "y", {0.0, 0.5, 1.2}, {0.8, 1.0, 2.5}));
    r.tables.back().columns.back().label = "y measured";
    PlotSpec spec = makePlot("p", "Curve", "curve", "x", {"y"});
    spec.reference_table = "measured";
    spec.reference_y = {"y"};
    QCustomPlot plot;
    plot.resize(600, 400);
    QVERIFY(fillPlot(plot, r, spec));
    requireMarkersInside(plot, 0.03, 3);
    // The scene's own points go by their column's label, which says what they are.
    QCOMPARE(plot.graph(1)->name(), QStringLiteral("y measured"));

    // A user's imported points (drawn as diamonds) likewise, beside the scene's own; named with their file's
    // title, which tells them apart from the scene's.
    Table user = points("paper", "y", {-0.3, 0.7}, {1.5, 3.0});
    user.title = "paper.csv";
    QVERIFY(fillPlot(plot, {{QStringLiteral("run 1"), &r}}, spec, {user}));
    requireMarkersInside(plot, 0.03, 5);
    QVERIFY2(plot.graph(2)->name().startsWith(QStringLiteral("paper.csv: ")), qPrintable(plot.graph(2)->name()));
  }

  // On a log y axis the room is counted in decades: points at 0.01 and 100 beside a curve from 1 to 2.
  void referencePointsOnALogAxis() {
    Results r = curves({{"y", "m", 2.0}});
    r.tables.push_back(points("measured", "y", {0.2, 0.8}, {0.01, 100.0}));
    PlotSpec spec = makePlot("p", "Curve", "curve", "x", {"y"}, true);
    spec.reference_table = "measured";
    spec.reference_y = {"y"};
    QCustomPlot plot;
    QVERIFY(fillPlot(plot, r, spec));
    requireMarkersInside(plot, 0.03, 2);
  }

  // A curve alone keeps the tight fit: no marker, no margin (the x range is exactly the data's 0 … 1).
  void curvesAloneAreFittedTightly() {
    const Results r = curves({{"y", "m", 2.0}});
    QCustomPlot plot;
    QVERIFY(fillPlot(plot, r, makePlot("p", "Curve", "curve", "x", {"y"})));
    QCOMPARE(plot.axisRect()->axis(QCPAxis::atBottom)->range().lower, 0.0);
    QCOMPARE(plot.axisRect()->axis(QCPAxis::atBottom)->range().upper, 1.0);
  }

  // A bending stress of 27 MPa and a torsional stress of 4 Pa (ratio 6.8e6): the torsional stress gets the right
  // axis, with its own label, a legend entry that says so, and a range that holds its values (2 … 4 Pa); the left
  // axis is labelled by the bending stress alone.
  void veryDifferentSizesGetTwoAxes() {
    const Results r = curves({{"bending", "Pa", 2.7e7}, {"torsion", "Pa", 4.0}});
    QCustomPlot plot;
    QVERIFY(fillPlot(plot, r, makePlot("p", "Stresses", "curve", "x", {"bending", "torsion"})));
    QCPAxis* left = plot.axisRect()->axis(QCPAxis::atLeft);
    QCPAxis* right = plot.axisRect()->axis(QCPAxis::atRight);
    QCOMPARE(plot.graphCount(), 2);
    QCOMPARE(plot.graph(0)->valueAxis(), left);
    QCOMPARE(plot.graph(1)->valueAxis(), right);
    QVERIFY(right->visible());
    QVERIFY(right->tickLabels());
    QVERIFY(right->range().lower <= 2.0 && right->range().upper >= 4.0);
    QVERIFY(right->range().size() < 10.0);  // its own scale, not the left's 1e7
    QVERIFY(left->range().upper >= 2.7e7);
    QCOMPARE(right->label(), QStringLiteral("torsion [Pa]"));
    QCOMPARE(left->label(), QStringLiteral("bending [Pa]"));
    QCOMPARE(plot.graph(1)->name(), QStringLiteral("torsion [Pa] (right axis)"));
    QVERIFY(!plot.graph(0)->name().contains(QStringLiteral("right axis")));
  }

  // Several columns on one axis are labelled by the plot's title; a title "Y against X" (or "Y vs X", with an
  // aside in brackets) gives the y axis Y only, so it fits beside the axis: "Bending frequencies [rad/s]".
  void aTitleAgainstXLabelsTheYAxisByItsYPart() {
    const Results r = curves({{"omega_1", "rad/s", 2.0}, {"omega_2", "rad/s", 4.0}});
    QCustomPlot plot;
    QVERIFY(fillPlot(plot, r, makePlot("p", "Bending frequencies against pretension ratio i_T", "curve", "x",
                                       {"omega_1", "omega_2"})));
    QCOMPARE(plot.axisRect()->axis(QCPAxis::atLeft)->label(), QStringLiteral("Bending frequencies [rad/s]"));
    QCustomPlot other;
    QVERIFY(fillPlot(other, r, makePlot("q", "Amplitude ratio vs reduced velocity (up-sweep)", "curve", "x",
                                        {"omega_1", "omega_2"})));
    QCOMPARE(other.axisRect()->axis(QCPAxis::atLeft)->label(), QStringLiteral("Amplitude ratio [rad/s]"));
  }

  // The threshold is a factor 100 of the largest |value|: a top tension of 2 MN with a horizontal force of 10 kN
  // (200×) is split, with 50 kN (40×) it is not.
  void splitAtAFactorOfHundred() {
    AxisSplit split = splitByMagnitude(curves({{"t", "N", 2e6}, {"h", "N", 1e4}}).tables[0], {"t", "h"});
    QCOMPARE(split.left, std::vector<std::string>{"t"});
    QCOMPARE(split.right, std::vector<std::string>{"h"});
    split = splitByMagnitude(curves({{"t", "N", 2e6}, {"h", "N", 5e4}}).tables[0], {"t", "h"});
    QCOMPARE(split.left, (std::vector<std::string>{"t", "h"}));
    QVERIFY(split.right.empty());
    // An all-zero column has no size to compare: it stays with the left axis.
    split = splitByMagnitude(curves({{"t", "N", 2e6}, {"z", "N", 0.0}}).tables[0], {"t", "z"});
    QVERIFY(split.right.empty());

    const Results similar = curves({{"t", "N", 2e6}, {"h", "N", 5e4}});
    QCustomPlot plot;
    QVERIFY(fillPlot(plot, similar, makePlot("p", "Top forces", "curve", "x", {"t", "h"})));
    QVERIFY(!plot.axisRect()->axis(QCPAxis::atRight)->visible());
    QCOMPARE(plot.graph(1)->valueAxis(), plot.axisRect()->axis(QCPAxis::atLeft));
  }

  // Right-axis columns that still differ by more than 100× among themselves get a second right axis: 27 MPa on the
  // left, 40 kPa on the right (675× smaller), 4 Pa (10 000× smaller again) on a further right axis outside it; each
  // axis holds its own column's range, and the legend says which axis a curve is on.
  void aThirdSizeGetsAThirdAxis() {
    const Results r = curves({{"bending", "Pa", 2.7e7}, {"shear", "Pa", 4.0e4}, {"torsion", "Pa", 4.0}});
    const auto tiers = magnitudeTiers(r.tables[0], {"bending", "shear", "torsion"});
    QCOMPARE(tiers, (std::vector<std::vector<std::string>>{{"bending"}, {"shear"}, {"torsion"}}));
    QCustomPlot plot;
    plot.resize(700, 400);
    QVERIFY(fillPlot(plot, r, makePlot("p", "Stresses", "curve", "x", {"bending", "shear", "torsion"})));
    const QList<QCPAxis*> right = plot.axisRect()->axes(QCPAxis::atRight);
    QCOMPARE(right.size(), 2);
    QCOMPARE(plot.graph(0)->valueAxis(), plot.axisRect()->axis(QCPAxis::atLeft));
    QCOMPARE(plot.graph(1)->valueAxis(), right[0]);
    QCOMPARE(plot.graph(2)->valueAxis(), right[1]);
    QVERIFY(right[1]->visible() && right[1]->tickLabels());
    QCOMPARE(right[0]->label(), QStringLiteral("shear [Pa]"));
    QCOMPARE(right[1]->label(), QStringLiteral("torsion [Pa]"));
    QVERIFY(right[0]->range().lower <= 2.0e4 && right[0]->range().upper >= 4.0e4 && right[0]->range().size() < 1e5);
    QVERIFY(right[1]->range().lower <= 2.0 && right[1]->range().upper >= 4.0 && right[1]->range().size() < 10.0);
    QCOMPARE(plot.graph(1)->name(), QStringLiteral("shear [Pa] (right axis)"));
    QCOMPARE(plot.graph(2)->name(), QStringLiteral("torsion [Pa] (right axis 2)"));

    // Within 100× of each other the right-axis columns share it: 40 kPa and 4 kPa (10×) with 27 MPa.
    QCOMPARE(magnitudeTiers(curves({{"b", "Pa", 2.7e7}, {"s", "Pa", 4.0e4}, {"t", "Pa", 4.0e3}}).tables[0],
                            {"b", "s", "t"}),
             (std::vector<std::vector<std::string>>{{"b"}, {"s", "t"}}));
    // Four sizes each 1000× apart make three axes at most: the smallest two share the third.
    QCOMPARE(magnitudeTiers(curves({{"a", "N", 1e9}, {"b", "N", 1e6}, {"c", "N", 1e3}, {"d", "N", 1.0}}).tables[0],
                            {"a", "b", "c", "d"}),
             (std::vector<std::vector<std::string>>{{"a"}, {"b"}, {"c", "d"}}));
    // An all-zero column stays on the left; one size alone is one tier.
    QCOMPARE(magnitudeTiers(curves({{"z", "N", 0.0}, {"t", "N", 2e6}}).tables[0], {"z", "t"}),
             (std::vector<std::vector<std::string>>{{"z", "t"}}));
  }

  // The legend's corner cover counts a line passing through a corner box, not only its points there: one segment
  // from (0, 0.7) to (0.4, 1) of the axes crosses the top-left box (0.3 × 0.2 of the axes; at x = 0.2 the line is
  // at 0.85) between its two points, which both lie outside it.
  void legendCoverCountsSegmentsThroughACorner() {
    Results r;
    Table& t = r.tables.emplace_back();
    t.name = "line";
    t.add("x", "m", {0.0, 0.4});
    t.add("y", "m", {0.7, 1.0});
    QCustomPlot plot;
    plot.resize(600, 400);
    QVERIFY(fillPlot(plot, r, makePlot("p", "Line", "line", "x", {"y"})));
    plot.xAxis->setRange(0.0, 1.0);
    plot.yAxis->setRange(0.0, 1.0);
    plot.replot();  // lays out the axes: their size in pixels
    const QRect rect = plot.axisRect()->rect();
    // Less the 12-pixel inset margin the cover adds: a box of 0.3 × 0.2 of the axes.
    const QSizeF legend(0.3 * rect.width() - 12.0, 0.2 * rect.height() - 12.0);
    const std::array<int, 4> cover = legendCornerCover(plot, *plot.axisRect(), legend);
    QCOMPARE(cover[0], 0);  // top right
    QCOMPARE(cover[1], 1);  // top left: the segment, neither of its points
    QCOMPARE(cover[2], 0);
    QCOMPARE(cover[3], 0);
  }

  // A curve that fills every corner (an oscillation over the whole range) leaves no corner to the legend: it goes
  // under the axes, its entries side by side; when the axes are zoomed to where a corner is empty, it goes inside.
  void legendGoesUnderTheAxesWhenEveryCornerHasACurve() {
    Results r;
    Table& t = r.tables.emplace_back();
    t.name = "wave";
    std::vector<double> x, a, b;
    for (int i = 0; i <= 2000; ++i) {
      x.push_back(i * 0.01);
      a.push_back(std::sin(2.0 * M_PI * x.back()));
      b.push_back(0.5 * std::cos(2.0 * M_PI * x.back()));
    }
    t.add("t", "s", x, "Time");
    t.add("a", "m", a, "Surge");
    t.add("b", "m", b, "Sway");
    QCustomPlot plot;
    plot.resize(800, 500);
    QVERIFY(fillPlot(plot, r, makePlot("p", "Motion", "wave", "t", {"a", "b"})));
    QCOMPARE(plot.axisRect()->insetLayout()->elementCount(), 0);
    auto* grid = plot.plotLayout();
    auto* legend = qobject_cast<QCPLegend*>(grid->element(grid->rowCount() - 1, 0));
    QVERIFY(legend);
    QCOMPARE(legend->itemCount(), 2);
    QCOMPARE(legend->columnCount(), 2);  // one row: both entries fit the width side by side
    // Zoomed into the first quarter period (the curves rise from the bottom left and fall to the right), the top
    // left is empty: the legend goes there.
    plot.xAxis->setRange(0.0, 0.25);
    plot.yAxis->setRange(-1.2, 1.2);
    placePlotLegend(plot);
    QCOMPARE(plot.axisRect()->insetLayout()->elementCount(), 1);
    QVERIFY(qobject_cast<QCPLegend*>(plot.axisRect()->insetLayout()->elementAt(0)));
    QCOMPARE(plot.axisRect()->insetLayout()->insetAlignment(0), Qt::AlignTop | Qt::AlignLeft);
    QCOMPARE(grid->rowCount(), 2);  // the title and the axes: the legend's row is gone
  }

  // In a narrow plot, legend entries wider than the plot are shortened with "…" in the middle; the whole text stays as the
  // graph's full name (the legend entry's tooltip and the hover read-out show it).
  void longLegendEntriesAreElidedInANarrowPlot() {
    const std::string long_name = "horizontal component of the top reaction force in the global frame";
    const Results r = curves({{long_name, "N", 2.0e4}, {"vertical component of the top reaction force", "N", 1.0e4}});
    QCustomPlot plot;
    plot.resize(260, 300);
    QVERIFY(fillPlot(plot, r, makePlot("p", "Top reaction", "curve", "x",
                                       {long_name, "vertical component of the top reaction force"})));
    // Both curves are in N on one axis: the axis label says so and the entries leave the unit out.
    QCOMPARE(plot.yAxis->label(), QStringLiteral("Top reaction [N]"));
    const QString full = QString::fromStdString(long_name);
    // Shortened in the middle ("…", or "..." where the font lacks the ellipsis): the end that tells entries apart
    // stays.
    QVERIFY2(plot.graph(0)->name().contains(QChar(0x2026)) || plot.graph(0)->name().contains(QStringLiteral("...")),
             qPrintable(plot.graph(0)->name()));
    QVERIFY2(plot.graph(0)->name().endsWith(QStringLiteral("global frame")), qPrintable(plot.graph(0)->name()));
    QVERIFY(plot.graph(0)->name().size() < full.size());
    QCOMPARE(fullGraphName(*plot.graph(0)), full);
    // Every legend entry fits the plot's width.
    const QFontMetrics metrics(plot.font());
    for (int i = 0; i < plot.graphCount(); ++i) QVERIFY(metrics.horizontalAdvance(plot.graph(i)->name()) < 260);
    // In a wide plot nothing is shortened.
    QCustomPlot wide;
    wide.resize(1600, 600);
    QVERIFY(fillPlot(wide, r, makePlot("p", "Top reaction", "curve", "x",
                                       {long_name, "vertical component of the top reaction force"})));
    QCOMPARE(wide.graph(0)->name(), full);
    QCOMPARE(fullGraphName(*wide.graph(0)), full);
  }

  // On a log y axis every size reads: one axis. Reference points of a right-axis column go on the right axis.
  void logAxisAndReferencePointsOfTheSmallColumn() {
    const Results r = curves({{"big", "m", 1e6}, {"small", "m", 1.0}});
    QCustomPlot plot;
    QVERIFY(fillPlot(plot, r, makePlot("p", "Sizes", "curve", "x", {"big", "small"}, true)));
    QVERIFY(!plot.axisRect()->axis(QCPAxis::atRight)->visible());

    Results with_points = r;
    with_points.tables.push_back(points("measured", "small", {0.5}, {3.0}));
    PlotSpec spec = makePlot("p", "Sizes", "curve", "x", {"big", "small"});
    spec.reference_table = "measured";
    spec.reference_y = {"small"};
    QVERIFY(fillPlot(plot, with_points, spec));
    QCOMPARE(plot.graphCount(), 3);
    QCOMPARE(plot.graph(2)->valueAxis(), plot.axisRect()->axis(QCPAxis::atRight));
    requireMarkersInside(plot, 0.03, 1);  // 3.0 lies above the curve's 0.5 … 1: the right axis grew to hold it
  }
};

QTEST_MAIN(TestPlotAxes)
#include "test_plot_axes.moc"
