// Many plots in one run (a riser run has about 14, from several tables). In the main window at 1366 × 768 the
// plot panel is too narrow for their tabs to show whole titles, so a plot list takes the tab bar's place: every
// title whole, under its group's heading, each entry showing its plot. Where the panel is wide enough, the plots are
// grouped by table behind a chooser above the tab bar, each group's tabs fit the bar unshortened with no scroll
// arrows, a group's shared title prefix ("Envelope: ") leaves its tabs but stays in their tooltips, and a tab chosen
// from outside (as --tab does) brings its group. Six plots or fewer stay plain tabs.
// The results are made here (riser-like names and titles), so the expected groups follow from them.
#include <algorithm>

#include <QAbstractItemView>
#include <QComboBox>
#include <QFontMetrics>
#include <QScreen>
#include <QStyle>
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

// The whole title of every plot of `r`, in order.
QStringList fullTitles(const Results& r) {
  QStringList titles;
  for (const PlotSpec& p : r.plots) titles << QString::fromStdString(p.title);
  return titles;
}

// A tab shows its whole text when it is at least as wide as the text and the style's padding of a tab.
bool tabShowsWholeText(QTabBar* bar, int i) {
  const int needed =
      bar->fontMetrics().horizontalAdvance(bar->tabText(i)) + bar->style()->pixelMetric(QStyle::PM_TabBarTabHSpace, nullptr, bar);
  return bar->tabRect(i).width() >= needed;
}

}  // namespace

class PlotGroupsTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void at1366x768APlotListShowsEveryTitleWhole() {
    MainWindow window(test::rodLibrary());
    window.resize(1366, 768);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    PlotPanel* plots = window.plots();
    const Results made = riserLikePlots();
    const QStringList titles = fullTitles(made);
    plots->showResults(std::make_shared<Results>(made), QStringLiteral("run 1"));
    QCoreApplication::processEvents();
    QCOMPARE(plots->count(), 14);
    QCOMPARE(plots->groups().size(), std::size_t(5));
    // About 400 pixels beside the 3D view: the history group's seven tabs would shorten to a letter or two.
    QVERIFY2(plots->width() < 600, qPrintable(QString::number(plots->width())));
    QVERIFY(plots->showsPlotList());
    PlotList* list = plots->plotList();
    QVERIFY(list->isVisible());
    QVERIFY(!plots->tabs()->tabBar()->isVisible());
    QVERIFY(!plots->groupBox()->isVisible());

    // 14 plots under 5 headings (the groups' titles, which cannot be chosen), each plot once, its whole title.
    QCOMPARE(list->count(), 19);
    QStringList headings, entries;
    for (int row = 0; row < list->count(); ++row) {
      if (list->isHeading(row)) {
        headings << list->itemText(row);
        QVERIFY(!(list->model()->flags(list->model()->index(row, 0)) & Qt::ItemIsEnabled));
      } else {
        QCOMPARE(list->itemText(row), titles[list->plotOfRow(row)]);
        entries << list->itemText(row);
      }
    }
    QCOMPARE(headings, QStringList({QStringLiteral("Probe points, end reactions and energies over time"),
                                    QStringLiteral("Amplitude envelopes along the riser (second half of the run)"),
                                    QStringLiteral("Profile at t = 24 s"),
                                    QStringLiteral("Fatigue damage at the joints (DNV C1)"), QStringLiteral("Modes")}));
    QCOMPARE(entries, titles);
    QCOMPARE(list->itemText(9), QStringLiteral("Envelope: displacement amplitude"));  // the prefix kept here

    // The open list is wide enough for its longest entry, and tall enough for all of them.
    list->showPopup();
    QAbstractItemView* popup = list->view();
    QTRY_VERIFY(popup->isVisible());
    // Each entry's size is its whole text (in its font: the headings are bold) and margins, and the open list,
    // once the window system has widened it, is at least that wide and tall.
    QTRY_VERIFY(popup->viewport()->width() >= popup->sizeHintForIndex(list->model()->index(0, 0)).width());
    int height = 0;
    for (int row = 0; row < list->count(); ++row) {
      const QModelIndex index = list->model()->index(row, 0);
      const QSize entry = popup->sizeHintForIndex(index);
      const QFont font = index.data(Qt::FontRole).isValid() ? index.data(Qt::FontRole).value<QFont>() : popup->font();
      QVERIFY(entry.width() >= QFontMetrics(font).horizontalAdvance(list->itemText(row)));
      QVERIFY2(entry.width() <= popup->viewport()->width(),
               qPrintable(QStringLiteral("%1: %2 px in %3").arg(list->itemText(row)).arg(entry.width())
                              .arg(popup->viewport()->width())));
      height += entry.height();
    }
    QVERIFY2(height <= popup->viewport()->height(), qPrintable(QString::number(height)));  // no scrolling
    // The screen, not the window: the open list is a window of its own.
    test::keepScreenshot(window.screen()->grabWindow(0).toImage(), QStringLiteral("plot_list_1366x768"));
    list->hidePopup();

    // Each entry shows its plot; the keyboard steps over headings.
    std::vector<int> reached(14, 0);
    for (int row = 0; row < list->count(); ++row) {
      if (list->isHeading(row)) continue;
      list->setCurrentIndex(row);
      QCOMPARE(plots->currentView(), plots->view(list->plotOfRow(row)));
      ++reached[list->plotOfRow(row)];
    }
    QCOMPARE(reached, std::vector<int>(14, 1));
    list->setCurrentIndex(list->rowOfPlot(6));  // the last of the first group; a heading follows
    list->setFocus();
    QTest::keyClick(list, Qt::Key_Down);
    QCOMPARE(plots->currentView(), plots->view(7));

    // A plot chosen from outside (as --tab does) is the list's entry.
    plots->tabs()->setCurrentIndex(12);
    QCOMPARE(list->currentText(), titles[12]);
    QCOMPARE(list->toolTip(), titles[12]);
    // New results of the same plots keep the chosen plot.
    plots->showResults(std::make_shared<Results>(riserLikePlots()), QStringLiteral("run 2"));
    QCOMPARE(plots->tabs()->currentIndex(), 12);
    QCOMPARE(list->currentText(), titles[12]);
  }

  void aWidePanelShowsGroupedTabsWithWholeTitles() {
    PlotPanel panel;
    panel.resize(1800, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.showResults(std::make_shared<Results>(riserLikePlots()), QStringLiteral("run 1"));
    QCoreApplication::processEvents();
    QVERIFY(!panel.showsPlotList());
    QVERIFY(panel.plotList()->isHidden());
    QComboBox* chooser = panel.groupBox();
    QVERIFY(chooser->isVisible());
    QCOMPARE(chooser->count(), 5);
    QCOMPARE(chooser->itemText(4), QStringLiteral("Modes"));  // an untitled table: its name made readable
    QTabWidget* tabs = panel.tabs();
    QTabBar* bar = tabs->tabBar();
    QVERIFY(bar->isVisible());
    std::vector<int> reached(14, 0);
    for (int g = 0; g < chooser->count(); ++g) {
      chooser->setCurrentIndex(g);
      QCoreApplication::processEvents();
      const auto& members = panel.groups()[g].plots;
      for (int i = 0; i < tabs->count(); ++i) {
        const bool in_group = std::find(members.begin(), members.end(), i) != members.end();
        QCOMPARE(tabs->isTabVisible(i), in_group);
        if (!in_group) continue;
        QVERIFY2(tabShowsWholeText(bar, i), qPrintable(tabs->tabText(i)));
        tabs->setCurrentIndex(i);  // reachable: choosing it shows its plot
        QCOMPARE(panel.currentView(), panel.view(i));
        QCOMPARE(chooser->currentIndex(), g);
        ++reached[i];
      }
      for (QToolButton* arrow : bar->findChildren<QToolButton*>()) QVERIFY(!arrow->isVisible());
    }
    QCOMPARE(reached, std::vector<int>(14, 1));  // every plot in exactly one group

    // "Envelope: " is shared by the group's titles: off the tabs, in the tooltips.
    QCOMPARE(tabs->tabText(7), QStringLiteral("displacement amplitude"));
    QCOMPARE(tabs->tabToolTip(7), QStringLiteral("Envelope: displacement amplitude"));
    QCOMPARE(tabs->tabText(0), QStringLiteral("Probe 1 displacement"));

    // A tab chosen from outside brings its group.
    chooser->setCurrentIndex(0);
    tabs->setCurrentIndex(12);
    QCOMPARE(chooser->currentIndex(), 3);
    QVERIFY(tabs->isTabVisible(12));
    QVERIFY(!tabs->isTabVisible(0));

    // Narrowed, the panel turns to the plot list (every tab available behind it, the chosen plot kept); widened
    // again, to the group's tabs.
    panel.resize(420, 600);
    QCoreApplication::processEvents();
    QVERIFY(panel.showsPlotList());
    QVERIFY(panel.plotList()->isVisible());
    QVERIFY(!bar->isVisible());
    QVERIFY(!chooser->isVisible());
    QCOMPARE(panel.plotList()->currentText(), QStringLiteral("Fatigue life along the riser"));
    for (int i = 0; i < tabs->count(); ++i) QVERIFY(tabs->isTabVisible(i));
    panel.resize(1800, 600);
    QCoreApplication::processEvents();
    QVERIFY(!panel.showsPlotList());
    QVERIFY(bar->isVisible());
    QCOMPARE(chooser->currentIndex(), 3);
    QCOMPARE(tabs->currentIndex(), 12);
    QVERIFY(!tabs->isTabVisible(0));
  }

  // A scene's declared groups (its registry entry's plot_groups) come first, each with its plots in the order of its
  // names; a plot in none of them keeps the group of its table; a group that holds no plot of the run is left out.
  void declaredGroupsComeFirstAndTablesTakeTheRest() {
    const Results made = riserLikePlots();
    const std::vector<PlotGroupSpec> declared = {
        {"Over time at the probes", {"history_Probe*_displacement", "history_Stress_at_the_probes"}},
        {"Along the riser", {"envelope_*", "profile_t24_*", "fatigue_*"}},
        {"Sweeps", {"frequency_*"}},  // none in this run
    };
    const std::vector<PlotGroup> groups = groupPlots(made, declared);
    QCOMPARE(groups.size(), std::size_t(4));
    QCOMPARE(groups[0].title, QStringLiteral("Over time at the probes"));
    QCOMPARE(groups[0].plots, std::vector<int>({0, 1, 2, 5}));
    QCOMPARE(groups[1].title, QStringLiteral("Along the riser"));
    QCOMPARE(groups[1].plots, std::vector<int>({7, 8, 9, 10, 11, 12}));
    QCOMPARE(groups[1].common_prefix, QString());  // "Envelope: " is not shared by the whole group
    QCOMPARE(groups[2].title, QStringLiteral("Probe points, end reactions and energies over time"));
    QCOMPARE(groups[2].plots, std::vector<int>({3, 4, 6}));  // the history's plots no group declared
    QCOMPARE(groups[3].title, QStringLiteral("Modes"));
    QVERIFY(plotGroupHolds(declared[0], "history_Probe_2_displacement"));
    QVERIFY(!plotGroupHolds(declared[0], "history_Probe_2_stress"));
    QVERIFY(plotGroupHolds({"", {"a*bc"}}, "abc"));  // "a" and "bc" with nothing between
    QVERIFY(!plotGroupHolds({"", {"ab*bc"}}, "abc"));  // head and tail may not overlap

    // In the panel: the declared groups are the plot list's headings, and declaring them regroups shown results.
    PlotPanel panel;
    panel.resize(420, 600);
    panel.showResults(std::make_shared<Results>(made), QStringLiteral("run 1"));
    QCOMPARE(panel.groups().size(), std::size_t(5));
    panel.setDeclaredGroups(declared);
    QCOMPARE(panel.groups().size(), std::size_t(4));
    QVERIFY(panel.showsPlotList());
    QCOMPARE(panel.plotList()->itemText(0), QStringLiteral("Over time at the probes"));
    QCOMPARE(panel.plotList()->itemText(4), QStringLiteral("Stress at the probes"));
    QCOMPARE(panel.plotList()->count(), 14 + 4);
  }

  // Six plots or fewer, or all from one table: plain tabs, no chooser, when their titles fit.
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
    QVERIFY(!panel.showsPlotList());
    for (int i = 0; i < 6; ++i) QVERIFY(panel.tabs()->isTabVisible(i));
    Results one_table;
    addTable(one_table, "history", "History", {"a", "b", "c", "d", "e", "f", "g", "h"});
    panel.showResults(std::make_shared<Results>(one_table), QStringLiteral("run 2"));
    QCOMPARE(panel.count(), 8);
    QVERIFY(panel.groups().empty());
    QVERIFY(!panel.showsPlotList());
    for (int i = 0; i < 8; ++i) QVERIFY(panel.tabs()->isTabVisible(i));
    // From many plots back to few: every tab shows again.
    panel.showResults(std::make_shared<Results>(riserLikePlots()), QStringLiteral("run 3"));
    QCOMPARE(panel.groups().size(), std::size_t(5));
    panel.showResults(std::make_shared<Results>(few), QStringLiteral("run 4"));
    QVERIFY(panel.groups().empty());
    QVERIFY(!panel.showsPlotList());
    for (int i = 0; i < 6; ++i) QVERIFY(panel.tabs()->isTabVisible(i));
    // Few plots with long titles in a narrow panel: the plot list, without headings.
    Results long_titles;
    addTable(long_titles, "history", "History",
             {"Horizontal displacement of the top", "Vertical displacement of the top", "Bending moment at the root"});
    panel.resize(300, 500);
    panel.showResults(std::make_shared<Results>(long_titles), QStringLiteral("run 5"));
    QVERIFY(panel.showsPlotList());
    QCOMPARE(panel.plotList()->count(), 3);
    QCOMPARE(panel.plotList()->itemText(1), QStringLiteral("Vertical displacement of the top"));
  }
};

QTEST_MAIN(PlotGroupsTest)
#include "test_plot_groups.moc"
