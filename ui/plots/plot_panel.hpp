// The plot tabs: one PlotView per PlotSpec of the shown run, a toolbar acting on the current tab
// (log axes, fit, reference data from a CSV, export as PNG/PDF/SVG/CSV of the shown run or of all
// kept runs) and an "Overlay runs" menu listing earlier runs of the same scene, whose curves are
// drawn dashed or in other colours on every tab. A run with many plots from several tables shows them in groups
// (plots/plot_groups.hpp): a group chooser above the tab bar, and the chosen group's tabs. Where the tabs would have
// to shorten their titles (a narrow panel), a plot list (plots/plot_list.hpp) takes the place of the group chooser
// and the tab bar.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include <QWidget>

#include "plots/plot_groups.hpp"
#include "plots/plot_list.hpp"
#include "plots/plot_view.hpp"
#include "run/run_controller.hpp"

class QAction;
class QComboBox;
class QMenu;
class QTabWidget;

namespace maris::ui {

class PlotPanel : public QWidget {
  Q_OBJECT
 public:
  explicit PlotPanel(QWidget* parent = nullptr);

  // Shows `results` (labelled `label`). A plot keeps its tab (and its view, zoom and reference
  // data) from one result to the next by name; a plot the results lack leaves the tab bar but its
  // view is kept for later results that have it again. So live partial results keep the user's
  // current tab, and the change between a live run's plots and the finished run's (which has more)
  // makes no new views after the first run (making a plot view and its first layout cost ~2 ms each).
  void showResults(std::shared_ptr<const Results> results, const QString& label);
  // A finished run's first plot: when the shown plot draws nothing but zeros (a statics-only run's time history) and
  // the user has not chosen a plot since the scenario was opened, the first plot (in the order they are offered)
  // that carries data is shown instead (plotCarriesData).
  void showPlotWithData();
  // Whether the user chose the shown plot (a tab, the plot list or the group chooser) since the last clear().
  bool userChosePlot() const { return plot_chosen_; }
  // The groups the shown scene declares (SceneDefinition::plot_groups); set before its results are shown. Shown
  // results are grouped again when they change.
  void setDeclaredGroups(const std::vector<PlotGroupSpec>& declared);
  // Runs offered for overlay (the shown one is skipped by id).
  void setAvailableRuns(const std::vector<RunRecord>& runs, quint64 shown_run);
  void setOverlay(quint64 run, bool on);
  void clear();

  int count() const { return static_cast<int>(views_.size()); }
  PlotView* view(int i) const { return views_.at(i); }
  PlotView* currentView() const;
  QTabWidget* tabs() const { return tabs_; }
  // The group chooser (hidden when the plots are not grouped) and the groups of the shown run (empty: none).
  QComboBox* groupBox() const { return group_box_; }
  const std::vector<PlotGroup>& groups() const { return groups_; }
  // The plot list (shown instead of the tab bar and the group chooser when the tabs would shorten their titles).
  PlotList* plotList() const { return plot_list_; }
  bool showsPlotList() const { return list_mode_; }

  // Reads a CSV (see plots/reference_data.hpp) and draws it as markers on the current plot, for this
  // and later runs. Returns false and says why (message()) if the file cannot be read.
  bool addReferenceFile(const QString& file);
  void clearReferences();  // of the current plot
  // The current plot's data for the shown run and every kept run of the scene, one "run" column first.
  void exportAllRunsCsv(const QString& file);

  // For the main window's Plot menu.
  QAction* addReferenceAction() const { return add_reference_; }
  QAction* clearReferenceAction() const { return clear_reference_; }
  QMenu* exportMenu() const { return export_menu_; }
  // The row of buttons above the plots (log axes, fit, overlay, reference data, export); it wraps when narrow.
  QWidget* toolBar() const { return toolbar_; }

 protected:
  void resizeEvent(QResizeEvent* event) override;

 signals:
  void message(const QString& text);  // export results and errors, for the status bar / log

 private:
  void rebuildTabs(const Results& results);
  // The kept view of `spec` (if its spec is the same) or a new one.
  PlotView* takeSpareView(const PlotSpec& spec);
  void redrawAll();
  // Tab texts, tooltips and the group chooser for the shown results' plots (views_ in their order).
  void regroup(const Results& results);
  // Shows the tabs of group `g` only (every tab when the plots are not grouped).
  void showGroup(int g);
  // Tabs when every group's tabs fit the panel's width unshortened, else the plot list.
  void choosePicker(bool force);
  int groupOfTab(int tab) const;
  void syncToolbar();
  void exportCurrent(const QString& suffix);

  QWidget* toolbar_;
  PlotTabs* tabs_;
  QComboBox* group_box_;
  PlotList* plot_list_;
  bool list_mode_ = false;
  std::vector<PlotGroup> groups_;
  std::vector<PlotGroupSpec> declared_groups_;
  bool grouping_ = false;  // inside showGroup: tab changes are its own
  bool plot_chosen_ = false;  // the user picked a plot: showPlotWithData leaves it
  QAction* log_x_;
  QAction* log_y_;
  QMenu* overlay_menu_;
  QMenu* export_menu_;
  QAction* add_reference_;
  QAction* clear_reference_;
  std::vector<PlotView*> views_;                 // the tabs, in order
  std::map<std::string, PlotView*> spare_views_;  // views of plots the shown results lack, by name
  std::shared_ptr<const Results> shown_;
  QString shown_label_;
  std::vector<RunRecord> runs_;
  std::set<quint64> overlaid_;
  quint64 shown_run_ = 0;
  std::string shown_scenario_;  // the shown run's scenario name (setAvailableRuns), for the all-runs CSV
  std::map<std::string, std::vector<Table>> references_;  // by plot name
};

}  // namespace maris::ui
