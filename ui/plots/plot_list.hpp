// The two ways the plot panel lets the user pick a plot. Tabs, when every tab's title fits the panel's width
// unshortened; otherwise a plot list: a drop-down of every plot's whole title, under the headings of its group
// (plots/plot_groups.hpp), whose open list is as wide as its longest title. On a 1366-pixel screen the panel beside
// the 3D view is about 400 pixels wide, where a riser run's 14 tabs would shrink to "T…" and "E…".
#pragma once

#include <vector>

#include <QComboBox>
#include <QTabBar>
#include <QTabWidget>

#include "plots/plot_groups.hpp"

namespace maris::ui {

// A tab widget that tells how wide a tab would be with its whole title (QTabBar's own size hint, which the
// bar shortens with its elide mode when the tabs do not fit).
class PlotTabs : public QTabWidget {
  Q_OBJECT
 public:
  explicit PlotTabs(QWidget* parent = nullptr);
  int unelidedTabWidth(int tab) const;

 private:
  class Bar : public QTabBar {
   public:
    using QTabBar::QTabBar;
    int fullWidth(int tab) const { return QTabBar::tabSizeHint(tab).width(); }
  };
  Bar* bar_;
};

// True when the tabs of every group (every tab when `groups` is empty) fit `room` pixels unshortened; one group's
// tabs are shown at a time.
bool tabsFitUnelided(const PlotTabs& tabs, const std::vector<PlotGroup>& groups, int room);

// The plot list: a drop-down of the plots (their whole titles), each group under a heading that cannot be chosen.
class PlotList : public QComboBox {
  Q_OBJECT
 public:
  explicit PlotList(QWidget* parent = nullptr);

  // One entry per title, in tab order; `groups` (may be empty) add their titles as headings.
  void setPlots(const QStringList& titles, const std::vector<PlotGroup>& groups);
  // Makes the entry of plot `tab` current without emitting plotChosen.
  void setCurrentPlot(int tab);
  // The plot of entry `row` (-1 for a heading).
  int plotOfRow(int row) const;
  int rowOfPlot(int tab) const;
  bool isHeading(int row) const { return plotOfRow(row) < 0; }

  void showPopup() override;

 signals:
  void plotChosen(int tab);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void colourHeading(int row);
  bool quiet_ = false;
};

}  // namespace maris::ui
