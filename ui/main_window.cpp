#include "main_window.hpp"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>

#include <algorithm>

#include "browser/scenario_browser.hpp"
#include "counted.hpp"
#include "document/scenario_document.hpp"
#include "editor/parameter_editor.hpp"
#include "plots/display_units.hpp"
#include "plots/plot_panel.hpp"
#include "run/live_results.hpp"
#include "run/results_summary.hpp"
#include "run/run_panel.hpp"
#include "scene_library.hpp"
#include "study/study_panel.hpp"
#include "study/study_plot_view.hpp"
#include "study/study_runner.hpp"
#include "themed_icon.hpp"
#include "view3d/scene_view.hpp"

namespace maris::ui {

namespace {
constexpr int kMaxRecentFiles = 8;
}

QSize defaultWindowSize(const QSize& available) {
  const QSize cap(1600, 1000);
  return QSize(std::min(cap.width(), available.width() * 9 / 10), std::min(cap.height(), available.height() * 9 / 10));
}

MainWindow::MainWindow(std::shared_ptr<const SceneLibrary> library, QWidget* parent)
    : QMainWindow(parent), library_(std::move(library)), document_(new ScenarioDocument(this)),
      runs_(new RunController(this)) {
  setObjectName(QStringLiteral("MarisMainWindow"));
  setAcceptDrops(true);
  setDockNestingEnabled(true);
  unsaved_prompt_ = [this] {
    return QMessageBox::question(this, tr("Unsaved changes"),
                                 tr("The scenario has unsaved changes. Save them first?"),
                                 QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  };

  view_ = new SceneView(this);
  plots_ = new PlotPanel(this);
  central_ = new QSplitter(Qt::Horizontal, this);
  central_->setObjectName(QStringLiteral("centralSplitter"));
  central_->addWidget(view_);
  central_->addWidget(plots_);
  central_->setStretchFactor(0, 1);
  central_->setStretchFactor(1, 1);
  setCentralWidget(central_);

  createActions();
  createDocks();
  validity_ = new QLabel(this);
  statusBar()->addPermanentWidget(validity_);

  connect(document_, &ScenarioDocument::errorsChanged, this, &MainWindow::updateRunEnabled);
  connect(document_, &ScenarioDocument::modifiedChanged, this, &MainWindow::updateTitle);
  connect(document_, &ScenarioDocument::filePathChanged, this, &MainWindow::updateTitle);
  connect(document_, &ScenarioDocument::scenarioReset, this, &MainWindow::updateTitle);
  connect(runs_, &RunController::runningChanged, this, &MainWindow::updateRunEnabled);
  connect(runs_, &RunController::finished, this, &MainWindow::onRunFinished);
  connect(runs_, &RunController::failed, this, &MainWindow::onRunFailed);
  connect(runs_, &RunController::cancelled, this, &MainWindow::onRunCancelled);
  live_ = new LiveResults(plots_, view_, this);
  live_->follow(runs_);
  connect(plots_, &PlotPanel::message, this, [this](const QString& text) { status(text); });
  connect(view_, &SceneView::message, this, [this](const QString& text) { status(text); });
  connect(summary_, &ResultsSummary::message, this, [this](const QString& text) { status(text); });
  connect(browser_, &ScenarioBrowser::exampleActivated, this, &MainWindow::openExample);
  connect(browser_, &ScenarioBrowser::fileActivated, this, &MainWindow::openFile);
  connect(browser_, &ScenarioBrowser::openFileRequested, this, &MainWindow::openFileDialog);
  connect(editor_, &ParameterEditor::sweepRequested, this, [this](const QString& path) {
    if (!study_dock_->isVisible()) showStudyDock();
    study_dock_->raise();
    study_->sweep(path);
  });
  connect(study_, &StudyPanel::caseOpened, this, &MainWindow::openStudyCase);
  connect(study_, &StudyPanel::message, this, [this](const QString& text) { status(text); });
  connect(study_, &StudyPanel::logged, this,
          [this](int level, const QString& text) { run_panel_->log(static_cast<RunPanel::Level>(level), text); });
  connect(study_->runner(), &StudyRunner::runningChanged, this, &MainWindow::updateRunEnabled);
  run_panel_->follow(study_->runner());

  // Sized to the screen it opens on; a geometry saved by an earlier session wins.
  if (const QScreen* screen = this->screen()) {
    const QRect available = screen->availableGeometry();
    resize(defaultWindowSize(available.size()));
    move(available.center() - QPoint(width() / 2, height() / 2));
  }
  restoreSettings();
  if (const BuiltinScenario* first = library_->defaultExample())
    openExample(QString::fromStdString(first->id));
  updateTitle();
  updateRunEnabled();
}

void MainWindow::showStudyDock() {
  // Docked beside the 3D view and the plots, the dock needs their minimum widths plus its own: where the
  // window is narrower than that (1366 px screens), docking it would widen the window past the screen's edge.
  // It then floats over the views' right part instead (double-click its title to dock it).
  const int separator = style()->pixelMetric(QStyle::PM_DockWidgetSeparatorExtent, nullptr, this);
  const int docked_width = minimumSizeHint().width() + study_dock_->minimumSizeHint().width() + separator;
  if (!study_dock_->isFloating() && docked_width > width()) {
    const int w = std::min(width() - 40, std::max(560, study_dock_->minimumSizeHint().width()));
    const int h = std::max(study_dock_->minimumSizeHint().height(), height() - 140);
    study_dock_->setFloating(true);
    study_dock_->setGeometry(QRect(mapToGlobal(QPoint(width() - w - 20, 90)), QSize(w, h)));
    study_dock_->show();
    return;
  }
  study_dock_->show();
  if (!study_dock_->isFloating())  // a quarter of the window for the study (its plot needs room)
    resizeDocks({left_dock_, study_dock_}, {std::min(440, width() / 4), std::max(380, width() / 4)}, Qt::Horizontal);
}

MainWindow::~MainWindow() {
  // The document is a child: QWidget's destructor deletes it after ours has run, and its undo stack
  // still emits signals then. Nothing of this window may receive them.
  document_->disconnect(this);
}

void MainWindow::createActions() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&New…"), QKeySequence::New, this, &MainWindow::newScenarioDialog);
  file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::openFileDialog);
  save_action_ = file->addAction(tr("&Save"), QKeySequence::Save, this, [this] { save(); });
  file->addAction(tr("Save &As…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), this, &MainWindow::saveAsDialog);
  file->addSeparator();
  report_action_ = file->addAction(tr("Export &Report Folder…"), QKeySequence(Qt::CTRL | Qt::Key_E), this,
                                   &MainWindow::reportDialog);
  file->addSeparator();
  file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
  edit->addAction(undo);
  edit->addAction(redo);

  QMenu* run = menuBar()->addMenu(tr("&Run"));
  run_action_ = run->addAction(themedIcon(QStyle::SP_MediaPlay), tr("&Run"), QKeySequence(Qt::CTRL | Qt::Key_R),
                               this, [this] { startRun(); });
  run_action_->setToolTip(tr("Run the scenario (Ctrl+R)"));
  cancel_action_ = run->addAction(themedIcon(QStyle::SP_MediaStop), tr("&Cancel"),
                                  QKeySequence(Qt::Key_Escape), this, &MainWindow::cancelRun);
  cancel_action_->setToolTip(tr("Cancel the running scenario (Esc)"));
  cancel_action_->setShortcutContext(Qt::WindowShortcut);

  QToolBar* tools = addToolBar(tr("Main"));
  tools->setObjectName(QStringLiteral("mainToolBar"));
  tools->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  tools->addAction(run_action_);
  tools->addAction(cancel_action_);
  tools->addSeparator();
  tools->addAction(undo);
  tools->addAction(redo);
}

void MainWindow::createDocks() {
  auto dock = [this](const QString& title, const QString& name, QWidget* content, Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(name);
    d->setWidget(content);
    addDockWidget(area, d);
    return d;
  };
  browser_ = new ScenarioBrowser(library_, this);
  editor_ = new ParameterEditor(document_, this);
  run_panel_ = new RunPanel(runs_, run_action_, cancel_action_, this);
  summary_ = new ResultsSummary(this);
  study_ = new StudyPanel(document_, library_, this);
  QDockWidget* scenarios = dock(tr("Scenarios"), QStringLiteral("scenarioDock"), browser_, Qt::LeftDockWidgetArea);
  QDockWidget* parameters = dock(tr("Parameters"), QStringLiteral("parameterDock"), editor_, Qt::LeftDockWidgetArea);
  QDockWidget* run = dock(tr("Run"), QStringLiteral("runDock"), run_panel_, Qt::BottomDockWidgetArea);
  QDockWidget* results = dock(tr("Results"), QStringLiteral("resultsDock"), summary_, Qt::BottomDockWidgetArea);
  left_dock_ = scenarios;
  study_dock_ = dock(tr("Study"), QStringLiteral("studyDock"), study_, Qt::RightDockWidgetArea);
  study_dock_->hide();  // shown by "Sweep this parameter…" or View ▸ Study
  splitDockWidget(scenarios, parameters, Qt::Vertical);
  splitDockWidget(run, results, Qt::Horizontal);
  resizeDocks({scenarios, parameters}, {220, 560}, Qt::Vertical);
  resizeDocks({scenarios}, {440}, Qt::Horizontal);
  resizeDocks({run}, {270}, Qt::Vertical);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  for (QDockWidget* d : {scenarios, parameters, run, results}) view->addAction(d->toggleViewAction());
  // View ▸ Study shows the dock where it fits (showStudyDock), not always beside the views.
  QAction* study_toggle = view->addAction(study_dock_->windowTitle());
  study_toggle->setCheckable(true);
  connect(study_toggle, &QAction::triggered, this, [this](bool show) {
    if (show) showStudyDock();
    else study_dock_->hide();
  });
  // Captures the dock, not the window: the dock reports a change while the window's children are destroyed.
  connect(study_dock_, &QDockWidget::visibilityChanged, study_toggle,
          [dock = study_dock_, study_toggle] { study_toggle->setChecked(!dock->isHidden()); });
  view->addSeparator();
  view->addAction(tr("Reset 3D &Camera"), this, [this] { view_->resetCamera(); });
  view->addSeparator();
  theme_menu_ = view->addMenu(tr("&Theme"));
  auto* themes = new QActionGroup(this);
  const std::pair<Theme, QString> choices[] = {
      {Theme::System, tr("&System")}, {Theme::Light, tr("&Light")}, {Theme::Dark, tr("&Dark")}};
  for (const auto& [theme, title] : choices) {
    QAction* a = theme_menu_->addAction(title, this, [this, theme = theme] { setTheme(theme); });
    a->setCheckable(true);
    a->setData(themeKey(theme));
    a->setChecked(theme == theme_);
    themes->addAction(a);
  }
  // Display units of plots, study plots, colour bars and the results dock, per kind of quantity (files stay SI).
  loadDisplayUnits();
  QMenu* units = view->addMenu(tr("&Units"));
  const std::pair<const char*, QString> kinds[] = {{"N", tr("&Force")}, {"Pa", tr("&Stress")}, {"m", tr("&Length")}};
  for (const auto& [si_unit, title] : kinds) {
    QMenu* kind = units->addMenu(title);
    auto* group = new QActionGroup(kind);
    for (const std::string& choice : displayUnitChoices(si_unit)) {
      QAction* a = kind->addAction(QString::fromStdString(choice), this, [this, si = std::string(si_unit), choice] {
        setDisplayUnit(si, choice);
        restoreShownRun();
        study_->plotView()->refresh();
      });
      a->setCheckable(true);
      a->setChecked(displayUnit(si_unit).unit == choice);
      group->addAction(a);
    }
  }
  QMenu* plot = menuBar()->addMenu(tr("&Plot"));
  plot->addAction(plots_->addReferenceAction());
  plot->addAction(plots_->clearReferenceAction());
  plot->addSeparator();
  plot->addMenu(plots_->exportMenu());
  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About Maris"), this, [this] {
    QMessageBox::about(this, tr("About Maris"),
                       tr("<b>Maris</b> %1<br>Ocean-engineering workbench: scenes, solvers, plots and 3D views over one "
                          "engine.").arg(QApplication::applicationVersion()));
  });
}

void MainWindow::restoreSettings() {
  QSettings settings;
  if (settings.contains(QStringLiteral("window/geometry")))
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
  if (settings.contains(QStringLiteral("window/state")))
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
  if (settings.contains(QStringLiteral("window/splitter")))
    central_->restoreState(settings.value(QStringLiteral("window/splitter")).toByteArray());
  recent_files_ = settings.value(QStringLiteral("recentFiles")).toStringList();
  const Theme saved = themeFromKey(settings.value(QStringLiteral("theme")).toString());
  if (saved != Theme::System) setTheme(saved);
  browser_->setRecentFiles(recent_files_);
}

void MainWindow::saveSettings() const {
  QSettings settings;
  settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("window/state"), saveState());
  settings.setValue(QStringLiteral("window/splitter"), central_->saveState());
  settings.setValue(QStringLiteral("recentFiles"), recent_files_);
}

void MainWindow::setTheme(Theme theme) {
  theme_ = theme;
  applyTheme(theme);
  for (QAction* a : theme_menu_->actions()) a->setChecked(a->data().toString() == themeKey(theme));
  QSettings().setValue(QStringLiteral("theme"), themeKey(theme));
}

void MainWindow::addRecentFile(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  recent_files_.removeAll(absolute);
  recent_files_.prepend(absolute);
  while (recent_files_.size() > kMaxRecentFiles) recent_files_.removeLast();
  browser_->setRecentFiles(recent_files_);
  QSettings().setValue(QStringLiteral("recentFiles"), recent_files_);
}

void MainWindow::updateTitle() {
  QString title = tr("Maris");
  if (!document_->isEmpty()) {
    const QString where = document_->filePath().isEmpty() ? (example_id_.isEmpty() ? tr("unsaved") : tr("built-in %1").arg(example_id_))
                                                          : QFileInfo(document_->filePath()).fileName();
    title = QStringLiteral("%1[*] — %2 — Maris").arg(QString::fromStdString(document_->scenario().name), where);
  }
  setWindowTitle(title);
  setWindowModified(document_->isModified());
}

void MainWindow::updateRunEnabled() {
  // A study and a single run share the cores and the progress bar: one at a time.
  const bool running = runs_->isRunning() || study_->isRunning();
  const bool valid = document_->isValid();
  run_action_->setEnabled(valid && !running);
  cancel_action_->setEnabled(running);
  const int problems = static_cast<int>(document_->errors().size());
  if (document_->isEmpty())
    validity_->setText(tr("No scenario"));
  else if (valid && !document_->warnings().empty() && !running)
    validity_->setText(tr("Ready, %1").arg(counted(static_cast<int>(document_->warnings().size()),
                                                           tr("plausibility warning"), tr("plausibility warnings"))));
  else if (valid)
    validity_->setText(running ? tr("Running…") : tr("Ready"));
  else
    validity_->setText(counted(problems, tr("invalid value"), tr("invalid values")));
  const bool doubtful = valid && !document_->warnings().empty();
  validity_->setStyleSheet(!valid && !document_->isEmpty() ? QStringLiteral("color: #d62728;")
                           : doubtful                     ? QStringLiteral("color: #a86400;")
                                                          : QString());
}

void MainWindow::status(const QString& text, int timeout_ms) { statusBar()->showMessage(text, timeout_ms); }

bool MainWindow::confirmDiscard() {
  if (!document_->isModified()) return true;
  switch (unsaved_prompt_()) {
    case QMessageBox::Save: return save();
    case QMessageBox::Discard: return true;
    default: return false;
  }
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!confirmDiscard()) {
    event->ignore();
    return;
  }
  runs_->cancel();
  study_->cancelStudy();
  saveSettings();
  event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  for (const QUrl& url : event->mimeData()->urls())
    if (url.isLocalFile() && url.toLocalFile().endsWith(QLatin1String(".json"), Qt::CaseInsensitive)) {
      event->acceptProposedAction();
      return;
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
  for (const QUrl& url : event->mimeData()->urls())
    if (url.isLocalFile()) {
      event->acceptProposedAction();
      openFile(url.toLocalFile());
      return;
    }
}

}  // namespace maris::ui
