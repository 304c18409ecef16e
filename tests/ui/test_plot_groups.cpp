// Many plots in one run (a riser run has about 14, from several tables): in the main window at 1366 × 768 they
// are grouped by table behind a chooser above the tab bar; each group's tabs fit the bar with no scroll arrows,
// every plot is reachable through its group, a group's shared title prefix ("Envelope: ") leaves its tabs but stays
// in their tooltips, a tab chosen from outside brings its group, and six plots or fewer stay plain tabs.
// The results are made here (riser-like names and titles), so the expected groups follow from them.
#include <algorithm>

#include <QComboBox>
#include <QTabBar>
#include <QTabWidget>
#include <QToolButton>
#include <QtTest>

#include "main_window.hpp"
#include "plots/plot_panel.hpp"
#include "test_scene.hpp"
#include "ui_test_support.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

void addTable(Results& r, const std::string& name, const std::string& title, const std::vector<std::string>& plots,
              const std::string& prefix = {}) {
  Table& t = r.tables.emplace_back();
  t.name = name;
  t.title = title;
  t.add("x", "s", {0.0, 1.0, 2.0}, "Time");
  for (const std::string& plot : plots) {
    std::string column = plot;
    std::replace(column.begin(), column.end(), ' ', '_');
    t.add(column, "m", {0.0, 1.0, 0.5}, plot);
    r.plots.push_back(makePlot(name + "_" + column, prefix + plot, name, "x", {column}));
  }
}

// 14 plots from 5 tables, titled as a riser run's.
Results riserLikePlots() {
  Results r;
  addTable(r, "history", "Probe points, end reactions and energies over time",
           {"Probe 1 displacement", "Probe 2 displacement", "Probe 3 displacement", "Top reaction",
            "Energy balance", "Stress at the probes", "Wave elevation"});
  addTable(r, "envelope", "Amplitude envelopes along the riser (second half of the run)",
           {"displacement amplitude", "bending stress amplitude", "tension amplitude"}, "Envelope: ");
  addTable(r, "profile_t24", "Profile at t = 24 s", {"stress", "shape"}, "Profile at t = 24 s: ");
  addTable(r, "fatigue", "Fatigue damage at the joints (DNV C1)", {"Fatigue life along the riser"});
  addTable(r, "modes", "", {"Natural frequencies"});
  return r;
}

}  // namespace

class PlotGroupsTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void manyPlotsAreGroupedAndEveryOneIsReachableAt1366x768() {
    MainWindow window(test::rodLibrary());
    window.resize(1366, 768);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    PlotPanel* plots = window.plots();
    const auto results = std::make_shared<Results>(riserLikePlots());
    plots->showResults(results, QStringLiteral("run 1"));
    QCoreApplication::processEvents();
    QCOMPARE(plots->count(), 14);
    QCOMPARE(plots->groups().size(), std::size_t(5));
    QComboBox* chooser = plots->groupBox();
    QVERIFY(chooser->isVisible());
    QCOMPARE(chooser->count(), 5);
    QCOMPARE(chooser->itemText(1), QStringLiteral("Amplitude envelopes along the riser (second half of the run)"));
    QCOMPARE(chooser->itemText(4), QStringLiteral("Modes"));  // an untitled table: its name made readable
    QTabWidget* tabs = plots->tabs();
    QTabBar* bar = tabs->tabBar();
    std::vector<int> reached(14, 0);
    for (int g = 0; g < chooser->count(); ++g) {
      chooser->setCurrentIndex(g);
      QCoreApplication::processEvents();
      int visible = 0, width = 0;
      for (int i = 0; i < tabs->count(); ++i) {
        const bool in_group = plots->groups()[g].plots.end() !=
                              std::find(plots->groups()[g].plots.begin(), plots->groups()[g].plots.end(), i);
        QCOMPARE(tabs->isTabVisible(i), in_group);
        if (!in_group) continue;
        ++visible;
        width += bar->tabRect(i).width();
        tabs->setCurrentIndex(i);  // reachable: choosing it shows its plot
        QCOMPARE(plots->currentView(), plots->view(i));
        QCOMPARE(chooser->currentIndex(), g);
        ++reached[i];
      }
      QCOMPARE(visible, static_cast<int>(plots->groups()[g].plots.size()));
      // The group's tabs fit the bar: no scroll arrows, the tabs' widths within the bar's.
      QVERIFY2(width <= bar->width(), qPrintable(QStringLiteral("group %1: tabs %2 px in a bar of %3 px")
                                                     .arg(chooser->itemText(g)).arg(width).arg(bar->width())));
      for (QToolButton* arrow : bar->findChildren<QToolButton*>()) QVERIFY(!arrow->isVisible());
    }
    QCOMPARE(reached, std::vector<int>(14, 1));  // every plot in exactly one group

    // "Envelope: " is shared by the group's titles: off the tabs, in the tooltips.
    QCOMPARE(tabs->tabText(7), QStringLiteral("displacement amplitude"));
    QCOMPARE(tabs->tabToolTip(7), QStringLiteral("Envelope: displacement amplitude"));
    QCOMPARE(tabs->tabText(0), QStringLiteral("Probe 1 displacement"));

    // A tab chosen from outside (as --tab does) brings its group.
    chooser->setCurrentIndex(0);
    tabs->setCurrentIndex(12);
    QCOMPARE(chooser->currentIndex(), 3);
    QVERIFY(tabs->isTabVisible(12));
    QVERIFY(!tabs->isTabVisible(0));
    test::keepScreenshot(window.grab().toImage(), QStringLiteral("plot_groups_1366x768"));

    // New results of the same plots keep the chosen group and tab.
    plots->showResults(std::make_shared<Results>(riserLikePlots()), QStringLiteral("run 2"));
    QCOMPARE(chooser->currentIndex(), 3);
    QCOMPARE(tabs->currentIndex(), 12);
  }

  // Six plots or fewer, or all from one table: plain tabs, no chooser.
  void fewPlotsStayPlainTabs() {
    PlotPanel panel;
    panel.resize(800, 500);
    Results few;
    addTable(few, "history", "History", {"a", "b", "c"});
    addTable(few, "profile", "Profile", {"d", "e", "f"});
    panel.showResults(std::make_shared<Results>(few), QStringLiteral("run 1"));
    QCOMPARE(panel.count(), 6);
    QVERIFY(panel.groups().empty());
    QVERIFY(panel.groupBox()->isHidden());
    for (int i = 0; i < 6; ++i) QVERIFY(panel.tabs()->isTabVisible(i));
    Results one_table;
    addTable(one_table, "history", "History", {"a", "b", "c", "d", "e", "f", "g", "h"});
    panel.showResults(std::make_shared<Results>(one_table), QStringLiteral("run 2"));
    QCOMPARE(panel.count(), 8);
    QVERIFY(panel.groups().empty());
    for (int i = 0; i < 8; ++i) QVERIFY(panel.tabs()->isTabVisible(i));
    // From many plots back to few: every tab shows again.
    panel.showResults(std::make_shared<Results>(riserLikePlots()), QStringLiteral("run 3"));
    QCOMPARE(panel.groups().size(), std::size_t(5));
    panel.showResults(std::make_shared<Results>(few), QStringLiteral("run 4"));
    QVERIFY(panel.groups().empty());
    for (int i = 0; i < 6; ++i) QVERIFY(panel.tabs()->isTabVisible(i));
  }
};

QTEST_MAIN(PlotGroupsTest)
#include "test_plot_groups.moc"
