#include "plots/plot_panel.hpp"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFileDialog>
#include <QMenu>
#include <QResizeEvent>
#include <QTabWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <stdexcept>

#include "core/resources.hpp"
#include "plots/plot_export.hpp"
#include "plots/reference_data.hpp"
#include "plots/result_plot.hpp"
#include "widgets/flow_layout.hpp"

namespace maris::ui {

PlotPanel::PlotPanel(QWidget* parent)
    : QWidget(parent), toolbar_(new QWidget(this)), tabs_(new PlotTabs(this)), group_box_(new QComboBox(this)),
      plot_list_(new PlotList(this)), overlay_menu_(new QMenu(tr("Overlay runs"), this)) {
  // The buttons wrap onto a second row in a narrow panel (a 1366-pixel screen) rather than hide behind an
  // overflow arrow; each is a flat tool button as in a toolbar.
  toolbar_->setObjectName(QStringLiteral("plotToolbar"));
  auto* buttons = new FlowLayout(toolbar_, 2);
  buttons->setContentsMargins(2, 2, 2, 2);
  auto button = [this, buttons](QAction* action) {
    auto* b = new QToolButton(toolbar_);
    b->setAutoRaise(true);
    if (action) b->setDefaultAction(action);
    buttons->addWidget(b);
    return b;
  };
  log_x_ = new QAction(tr("Log x"), this);
  log_x_->setCheckable(true);
  button(log_x_);
  log_y_ = new QAction(tr("Log y"), this);
  log_y_->setCheckable(true);
  button(log_y_);
  auto* fit = new QAction(tr("Fit"), this);
  connect(fit, &QAction::triggered, this, [this] {
    if (auto* v = currentView()) v->resetZoom();
  });
  fit->setToolTip(tr("Fit the axes to the data (or double-click the plot)"));
  button(fit);
  auto* overlay_button = button(nullptr);
  overlay_button->setText(tr("Overlay runs"));
  overlay_button->setMenu(overlay_menu_);
  overlay_button->setPopupMode(QToolButton::InstantPopup);
  overlay_button->setToolTip(tr("Draw earlier runs of this scene on the same axes"));
  auto* reference_menu = new QMenu(tr("Reference data"), this);
  add_reference_ = reference_menu->addAction(tr("Add reference data…"), this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("Add reference data"), QDir::homePath(),
                                                      tr("CSV files (*.csv *.txt);;All files (*)"));
    if (!file.isEmpty()) addReferenceFile(file);
  });
  add_reference_->setToolTip(tr("Draw points from a CSV file (names row, optional units row, numbers) on this plot"));
  clear_reference_ = reference_menu->addAction(tr("Remove reference data"), this, [this] { clearReferences(); });
  auto* reference_button = button(nullptr);
  reference_button->setText(tr("Reference data"));
  reference_button->setMenu(reference_menu);
  reference_button->setPopupMode(QToolButton::InstantPopup);
  export_menu_ = new QMenu(tr("Export"), this);
  export_menu_->addAction(tr("Plot as PNG…"), this, [this] { exportCurrent(QStringLiteral("png")); });
  export_menu_->addAction(tr("Plot as PDF…"), this, [this] { exportCurrent(QStringLiteral("pdf")); });
  export_menu_->addAction(tr("Plot as SVG…"), this, [this] { exportCurrent(QStringLiteral("svg")); });
  export_menu_->addAction(tr("Data as CSV…"), this, [this] { exportCurrent(QStringLiteral("csv")); });
  export_menu_->addAction(tr("Data of all kept runs as CSV…"), this, [this] { exportCurrent(QStringLiteral("all.csv")); });
  auto* export_button = button(nullptr);
  export_button->setObjectName(QStringLiteral("plotExportButton"));
  export_button->setText(tr("Export"));
  export_button->setMenu(export_menu_);
  export_button->setPopupMode(QToolButton::InstantPopup);
  tabs_->setDocumentMode(true);
  // Titles that do not fit are shortened (the tooltip has the whole), before the bar needs scroll arrows.
  tabs_->setElideMode(Qt::ElideRight);
  group_box_->setObjectName(QStringLiteral("plotGroup"));
  group_box_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  group_box_->setMinimumContentsLength(16);
  group_box_->setToolTip(tr("Plots of this group are shown as tabs"));
  group_box_->hide();
  connect(group_box_, &QComboBox::currentIndexChanged, this, [this](int g) {
    if (!grouping_) showGroup(g);
  });
  plot_list_->hide();
  connect(plot_list_, &PlotList::plotChosen, tabs_, &QTabWidget::setCurrentIndex);
  // The user's own choices of a plot (not the panel's, nor a --tab from the command line).
  connect(plot_list_, &PlotList::plotChosen, this, [this] { plot_chosen_ = true; });
  connect(tabs_, &QTabWidget::tabBarClicked, this, [this] { plot_chosen_ = true; });
  connect(group_box_, &QComboBox::activated, this, [this] { plot_chosen_ = true; });

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(toolbar_);
  // Above the tabs, not beside them: the tab bar keeps the panel's whole width.
  layout->addWidget(group_box_);
  layout->addWidget(plot_list_);
  layout->addWidget(tabs_, 1);

  connect(log_x_, &QAction::toggled, this, [this](bool on) {
    if (auto* v = currentView()) v->setLogX(on);
  });
  connect(log_y_, &QAction::toggled, this, [this](bool on) {
    if (auto* v = currentView()) v->setLogY(on);
  });
  connect(tabs_, &QTabWidget::currentChanged, this, [this](int tab) {
    // A tab chosen from outside (a test, --tab) brings its group.
    if (!grouping_ && !groups_.empty() && groupOfTab(tab) >= 0 && groupOfTab(tab) != group_box_->currentIndex())
      group_box_->setCurrentIndex(groupOfTab(tab));
    plot_list_->setCurrentPlot(tab);
    syncToolbar();
  });
  syncToolbar();
}

PlotView* PlotPanel::currentView() const {
  const int i = tabs_->currentIndex();
  return i >= 0 && i < count() ? views_[i] : nullptr;
}

void PlotPanel::clear() {
  shown_.reset();
  runs_.clear();
  overlaid_.clear();
  overlay_menu_->clear();
  tabs_->clear();
  groups_.clear();
  group_box_->clear();
  group_box_->hide();
  plot_list_->clear();
  plot_list_->hide();
  list_mode_ = false;
  plot_chosen_ = false;
  tabs_->tabBar()->show();
  qDeleteAll(views_);
  views_.clear();
  for (auto& [name, view] : spare_views_) delete view;
  spare_views_.clear();
  syncToolbar();
}

void PlotPanel::showResults(std::shared_ptr<const Results> results, const QString& label) {
  shown_ = std::move(results);
  shown_label_ = label;
  if (!shown_) return;
  rebuildTabs(*shown_);
  redrawAll();
}

void PlotPanel::showPlotWithData() {
  if (plot_chosen_ || !shown_) return;
  const int current = tabs_->currentIndex();
  if (current >= 0 && current < count() && plotCarriesData(*shown_, views_[current]->spec())) return;
  std::vector<int> offered;  // the groups' plots in their order, else the tabs'
  for (const PlotGroup& g : groups_) offered.insert(offered.end(), g.plots.begin(), g.plots.end());
  if (offered.empty())
    for (int i = 0; i < count(); ++i) offered.push_back(i);
  for (int i : offered)
    if (i < count() && plotCarriesData(*shown_, views_[i]->spec())) {
      tabs_->setCurrentIndex(i);
      return;
    }
}

void PlotPanel::rebuildTabs(const Results& results) {
  const std::vector<PlotSpec>& specs = results.plots;
  bool same = static_cast<int>(specs.size()) == count();
  for (int i = 0; same && i < count(); ++i) same = views_[i]->spec() == specs[i];
  if (same) return;
  // Tabs are removed and inserted one by one, not cleared and added again: each change of the
  // current tab shows a view, and a shown view with new data redraws (~8 ms each).
  auto wanted = [&](const PlotView* view) {
    return std::any_of(specs.begin(), specs.end(), [&](const PlotSpec& s) { return view->spec() == s; });
  };
  for (int i = count() - 1; i >= 0; --i)
    if (!wanted(views_[i])) {
      tabs_->removeTab(i);
      views_[i]->hide();
      spare_views_[views_[i]->spec().name] = views_[i];
      views_.erase(views_.begin() + i);
    }
  for (int i = 0; i < static_cast<int>(specs.size()); ++i) {
    const PlotSpec& spec = specs[i];
    if (i < count() && views_[i]->spec() == spec) continue;
    // A kept tab further on (plots in another order): take it out and put it here.
    PlotView* view = nullptr;
    for (int j = i + 1; j < count() && !view; ++j)
      if (views_[j]->spec() == spec) {
        view = views_[j];
        tabs_->removeTab(j);
        views_.erase(views_.begin() + j);
      }
    if (!view) view = takeSpareView(spec);
    views_.insert(views_.begin() + i, view);
    tabs_->insertTab(i, view, plotTabText(spec));
  }
  regroup(results);
  syncToolbar();
}

void PlotPanel::regroup(const Results& results) {
  const QString shown_group =
      group_box_->currentIndex() >= 0 ? group_box_->currentText() : QString();
  groups_ = groupPlots(results, declared_groups_);
  QStringList titles;
  for (int i = 0; i < count(); ++i) {
    const int g = groupOfTab(i);
    tabs_->setTabText(i, plotTabText(views_[i]->spec(), g >= 0 ? &groups_[g] : nullptr));
    titles << plotTabText(views_[i]->spec());
    tabs_->setTabToolTip(i, titles.back());
  }
  plot_list_->setPlots(titles, groups_);
  plot_list_->setCurrentPlot(tabs_->currentIndex());
  grouping_ = true;
  group_box_->clear();
  for (const PlotGroup& g : groups_) {
    group_box_->addItem(g.title);
    group_box_->setItemData(group_box_->count() - 1, g.title, Qt::ToolTipRole);
  }
  // The group of the current tab stays chosen (else the group of the same title, else the first).
  int g = groupOfTab(tabs_->currentIndex());
  if (g < 0) g = std::max(0, group_box_->findText(shown_group));
  group_box_->setCurrentIndex(groups_.empty() ? -1 : g);
  grouping_ = false;
  choosePicker(true);
}

void PlotPanel::choosePicker(bool force) {
  const bool list = count() > 0 && !tabsFitUnelided(*tabs_, groups_, width());
  if (list == list_mode_ && !force) return;
  list_mode_ = list;
  tabs_->tabBar()->setVisible(!list);
  plot_list_->setVisible(list);
  group_box_->setVisible(!list && !groups_.empty());
  showGroup(groups_.empty() ? -1 : group_box_->currentIndex());
}

void PlotPanel::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  choosePicker(false);
}

int PlotPanel::groupOfTab(int tab) const {
  for (int g = 0; g < static_cast<int>(groups_.size()); ++g)
    if (std::find(groups_[g].plots.begin(), groups_[g].plots.end(), tab) != groups_[g].plots.end()) return g;
  return -1;
}

void PlotPanel::showGroup(int g) {
  grouping_ = true;
  // The plot list offers every plot: no tab is hidden behind it.
  const bool grouped = !list_mode_ && g >= 0 && g < static_cast<int>(groups_.size());
  // The group's tabs are shown and one of them made current before the others hide, so the current tab never
  // falls into a hidden one.
  for (int i = 0; i < count(); ++i)
    if (!grouped || groupOfTab(i) == g) tabs_->setTabVisible(i, true);
  if (grouped && groupOfTab(tabs_->currentIndex()) != g) tabs_->setCurrentIndex(groups_[g].plots.front());
  if (grouped)
    for (int i = 0; i < count(); ++i)
      if (groupOfTab(i) != g) tabs_->setTabVisible(i, false);
  grouping_ = false;
  syncToolbar();
}

PlotView* PlotPanel::takeSpareView(const PlotSpec& spec) {
  if (auto it = spare_views_.find(spec.name); it != spare_views_.end()) {
    PlotView* view = it->second;
    spare_views_.erase(it);
    if (view->spec() == spec) return view;
    delete view;  // a plot of the same name with another table or columns is a new plot
  }
  auto* view = new PlotView(spec, tabs_);
  if (auto it = references_.find(spec.name); it != references_.end()) view->setReferences(it->second);
  view->setObjectName(QString::fromStdString("plot:" + spec.name));
  return view;
}

void PlotPanel::setDeclaredGroups(const std::vector<PlotGroupSpec>& declared) {
  if (declared == declared_groups_) return;
  declared_groups_ = declared;
  if (shown_) regroup(*shown_);
}

void PlotPanel::setAvailableRuns(const std::vector<RunRecord>& runs, quint64 shown_run) {
  runs_.clear();
  overlay_menu_->clear();
  shown_run_ = shown_run;
  for (const auto& r : runs) {
    if (r.id == shown_run) shown_scenario_ = r.scenario.name;
    if (r.id == shown_run) continue;
    runs_.push_back(r);
    QAction* a = overlay_menu_->addAction(r.label);
    a->setCheckable(true);
    a->setChecked(overlaid_.count(r.id) > 0);
    const quint64 id = r.id;
    connect(a, &QAction::toggled, this, [this, id](bool on) { setOverlay(id, on); });
  }
  if (runs_.empty()) overlay_menu_->addAction(tr("(no other finished runs)"))->setEnabled(false);
  // Forget overlays of runs that are gone.
  std::set<quint64> still;
  for (const auto& r : runs_)
    if (overlaid_.count(r.id)) still.insert(r.id);
  overlaid_ = std::move(still);
  redrawAll();
}

void PlotPanel::setOverlay(quint64 run, bool on) {
  if (on)
    overlaid_.insert(run);
  else
    overlaid_.erase(run);
  redrawAll();
}

void PlotPanel::redrawAll() {
  if (!shown_) return;
  std::vector<PlotView::Source> sources{{shown_label_, shown_}};
  for (const auto& r : runs_)
    if (overlaid_.count(r.id)) sources.push_back({r.label, r.results});
  for (auto* view : views_) view->setSources(sources);
}

void PlotPanel::syncToolbar() {
  PlotView* v = currentView();
  const QSignalBlocker bx(log_x_), by(log_y_);
  log_x_->setEnabled(v);
  log_y_->setEnabled(v);
  log_x_->setChecked(v && v->logX());
  log_y_->setChecked(v && v->logY());
  add_reference_->setEnabled(v);
  clear_reference_->setEnabled(v && !v->references().empty());
}

bool PlotPanel::addReferenceFile(const QString& file) {
  PlotView* v = currentView();
  if (!v) {
    emit message(tr("No plot to add reference data to: run the scenario first."));
    return false;
  }
  try {
    // The engine's data-file gate: regular files only, size, rows and columns bounded.
    const std::string text = readDataText(file.toStdString(), "", "reference data");
    Table table = tableFromCsv(text, QFileInfo(file).completeBaseName().toStdString());
    std::vector<Table>& kept = references_[v->spec().name];
    kept.push_back(std::move(table));
    v->setReferences(kept);
    QString note = tr("Reference data %1 added to %2").arg(QFileInfo(file).fileName(), QString::fromStdString(v->spec().name));
    if (shown_)
      for (const auto& n : referenceUnitMismatches(kept.back(), *shown_, v->spec()))
        note += QStringLiteral("; ") + QString::fromStdString(n);
    emit message(note);
    syncToolbar();
    return true;
  } catch (const std::exception& e) {
    emit message(tr("Could not read reference data: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
}

void PlotPanel::clearReferences() {
  PlotView* v = currentView();
  if (!v) return;
  references_.erase(v->spec().name);
  v->setReferences({});
  syncToolbar();
}

void PlotPanel::exportAllRunsCsv(const QString& file) {
  PlotView* v = currentView();
  if (!v || !shown_) throw std::runtime_error("no plot with data to export");
  std::vector<RunData> runs{{shown_run_, shown_.get(), shown_scenario_}};
  for (const auto& r : runs_) runs.push_back({r.id, r.results.get(), r.scenario.name});
  std::sort(runs.begin(), runs.end(), [](const RunData& a, const RunData& b) { return a.id < b.id; });
  writeRunsCsv(file.toStdString(), runs, v->spec());
}

void PlotPanel::exportCurrent(const QString& suffix) {
  PlotView* v = currentView();
  if (!v || !v->hasData()) {
    emit message(tr("Nothing to export: run the scenario first."));
    return;
  }
  const bool all_runs = suffix == QLatin1String("all.csv");
  const QString suggested = QDir::home().filePath(QString::fromStdString(v->spec().name) + (all_runs ? "_runs." : ".") +
                                                  (all_runs ? QStringLiteral("csv") : suffix));
  const QString file = QFileDialog::getSaveFileName(this, tr("Export plot"), suggested,
                                                    QStringLiteral("*.%1").arg(all_runs ? QStringLiteral("csv") : suffix));
  if (file.isEmpty()) return;
  try {
    if (all_runs)
      exportAllRunsCsv(file);
    else
      v->exportTo(file);
    emit message(tr("Exported %1").arg(file));
  } catch (const std::exception& e) {
    emit message(tr("Export failed: %1").arg(QString::fromUtf8(e.what())));
  }
}

}  // namespace maris::ui
